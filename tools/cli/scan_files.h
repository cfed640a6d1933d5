#pragma once

// The per-scan files of a run over scans (mlndt_odometry, mlndt_localize;
// docs/json_schema.md): the trajectory as trajectory_kitti.txt and
// trajectory_tum.txt (stamped, the header saying where the stamps come
// from), and scans.csv and scans.json with one row / object per result,
// made from the result's table (result_csv.h, result_json.h): the scan's
// name in "file" (the CSV's first column, the JSON's last key), the
// registration's trace left out (JSON only would be ~25 kB a scan).

#include <string>
#include <vector>

#include "mlndt/common/result_table.h"
#include "mlndt/common/types.h"
#include "tools/cli/scan_input.h"

namespace mlndt {
namespace tools {

// A scan's place in the trajectory: its index in the input, its stamp [s]
// and its pose in the trajectory's frame.
struct ScanPose {
  size_t index = 0;
  double stamp_s = 0.0;
  Isometry3d pose = Isometry3d::Identity();
};

// The four files into `dir`, `tool` naming the JSON's writer; `results`
// point at structs of `table`, one per entry of `poses`.
bool WriteScanFiles(const std::string& dir,
                    const std::string& tool,
                    const ScanInput& input,
                    const ResultTable& table,
                    const std::vector<const void*>& results,
                    const std::vector<ScanPose>& poses,
                    std::string* error);

// The same for a vector of results, `pose_of(result)` giving its ScanPose.
template <typename R, typename PoseOf>
bool WriteScanFilesOf(const std::string& dir,
                      const std::string& tool,
                      const ScanInput& input,
                      const ResultTable& table,
                      const std::vector<R>& results,
                      PoseOf pose_of,
                      std::string* error) {
  std::vector<const void*> pointers;
  std::vector<ScanPose> poses;
  for (const R& r : results) {
    pointers.push_back(&r);
    poses.push_back(pose_of(r));
  }
  return WriteScanFiles(dir, tool, input, table, pointers, poses, error);
}

}  // namespace tools
}  // namespace mlndt
