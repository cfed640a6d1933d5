#include "tools/cli/scan_files.h"

#include <utility>

#include "lab/eval/trajectory_io.h"
#include "mlndt/common/atomic_file.h"
#include "tools/cli/json_output.h"
#include "tools/cli/result_csv.h"
#include "tools/cli/result_json.h"

namespace mlndt {
namespace tools {
namespace {

// scans.json: the tool's header and one object per scan.
Json ScansJson(const std::string& tool,
               const ResultTable& table,
               const std::vector<const void*>& results,
               const CsvColumn& file) {
  Json scans = Json::array();
  for (size_t k = 0; k < results.size(); ++k) {
    Json scan = ResultJson(table, results[k]);
    if (scan.contains("registration")) scan["registration"].erase("trace");
    scan["file"] = file.cells[k];
    scans.push_back(std::move(scan));
  }
  Json json = ToolJson(tool);
  json["scans"] = std::move(scans);
  return json;
}

}  // namespace

bool WriteScanFiles(const std::string& dir,
                    const std::string& tool,
                    const ScanInput& input,
                    const ResultTable& table,
                    const std::vector<const void*>& results,
                    const std::vector<ScanPose>& poses,
                    std::string* error) {
  Trajectory trajectory;
  CsvColumn file{"file", {}};
  for (const ScanPose& p : poses) {
    if (!trajectory.TryAdd(p.stamp_s, p.pose, error)) {
      *error = "scan " + input.name(p.index) + ": " + *error;
      return false;
    }
    file.cells.push_back(input.name(p.index));
  }
  return WriteTrajectory(dir + "/trajectory_kitti.txt",
                         TrajectoryFormat::KITTI,
                         trajectory,
                         error) &&
         WriteTrajectory(dir + "/trajectory_tum.txt",
                         TrajectoryFormat::TUM,
                         trajectory,
                         input.TumComment(),
                         error) &&
         WriteFileAtomically(
             dir + "/scans.csv", ResultCsv(table, results, {file}), error) &&
         WriteJsonFile(
             dir + "/scans.json", ScansJson(tool, table, results, file), error);
}

}  // namespace tools
}  // namespace mlndt
