#include "tools/cli/eval_output.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "lab/report/text_format.h"
#include "tools/cli/result_json.h"

namespace mlndt {
namespace tools {
namespace {

void PrintSegmentLines(const TrajectoryEvaluationOptions& options,
                       const std::vector<TrajectoryEvaluation>& results) {
  for (const TrajectoryEvaluation& r : results) {
    if (r.kitti.lengths.empty()) {
      std::printf(
          "%s: KITTI segments: none (the reference path is %.1f m, shorter "
          "than %g m)\n",
          r.file.c_str(),
          r.path_length_m,
          *std::min_element(options.segments.lengths_m.begin(),
                            options.segments.lengths_m.end()));
      continue;
    }
    std::printf("%s: KITTI segments by length:", r.file.c_str());
    for (const KittiLengthErrors& l : r.kitti.lengths) {
      std::printf(" %g m (%zu): %.3f %% %.5f deg/m;",
                  l.length_m,
                  l.num_segments,
                  l.translation_error_percent,
                  l.rotation_error_deg_per_m);
    }
    std::printf("\n");
  }
}

}  // namespace

void PrintEvaluations(const TrajectoryEvaluationOptions& options,
                      const std::string& alignment_flag,
                      const EvaluationReference& reference,
                      const std::vector<TrajectoryEvaluation>& results) {
  std::printf(
      "reference: %s (%s, %zu poses); ATE after %s alignment, RPE "
      "over %d frame(s)\n",
      reference.path.c_str(),
      TrajectoryFormatToString(reference.format),
      reference.trajectory.size(),
      alignment_flag.c_str(),
      options.delta);
  std::printf(
      "| estimate | format | pairs | length [m] | ATE rmse [m] | ATE mean [m] "
      "| ATE max [m] | RPE t rmse [m] | RPE r rmse [deg] | KITTI t [%%] | "
      "KITTI r [deg/m] |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const TrajectoryEvaluation& r : results) {
    const bool has_rpe = r.rpe_pairs > 0;
    std::printf("| %s | %s | %zu | %s | %s | %s | %s | %s | %s | %s | %s |\n",
                r.file.c_str(),
                TrajectoryFormatToString(r.format),
                r.pairs,
                Fmt(r.path_length_m, 2).c_str(),
                Fmt(r.ate.rmse_m, 4).c_str(),
                Fmt(r.ate.errors.mean, 4).c_str(),
                Fmt(r.ate.errors.max, 4).c_str(),
                Fmt(has_rpe ? r.rpe.translation_rmse_m : NAN, 4).c_str(),
                Fmt(has_rpe ? r.rpe.rotation_rmse_deg : NAN, 4).c_str(),
                Fmt(r.kitti.translation_error_percent, 3).c_str(),
                Fmt(r.kitti.rotation_error_deg_per_m, 5).c_str());
  }
  PrintSegmentLines(options, results);
}

void PrintChain(const ReferenceChain& chain,
                const std::string& pairs_path,
                const std::string& output) {
  std::string list;
  for (size_t k = 0; !chain.consecutive() && k < chain.scans.size(); ++k) {
    list += (k ? ", " : ": ") + std::to_string(chain.scans[k]);
  }
  std::printf("chained %zu poses (scans %lld..%lld%s) from %s -> %s\n",
              chain.poses.size(),
              static_cast<long long>(chain.scans.front()),
              static_cast<long long>(chain.scans.back()),
              list.c_str(),
              pairs_path.c_str(),
              output.c_str());
}

Json EvaluationsJson(const TrajectoryEvaluationOptions& options,
                     const EvaluationReference& reference,
                     const std::vector<TrajectoryEvaluation>& results) {
  Json estimates = Json::array();
  for (const TrajectoryEvaluation& r : results) {
    estimates.push_back(ResultJsonOf(TrajectoryEvaluationTable(), r));
  }
  Json json = ToolJson("mlndt_eval");
  json["reference"] = reference.path;
  json["reference_format"] = TrajectoryFormatToString(reference.format);
  json["reference_poses"] = reference.trajectory.size();
  json["alignment"] = TrajectoryAlignmentToString(options.alignment);
  json["delta"] = options.delta;
  json["estimates"] = estimates;
  return json;
}

}  // namespace tools
}  // namespace mlndt
