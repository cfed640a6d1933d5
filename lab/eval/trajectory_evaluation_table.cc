#include <cstdint>
#include <limits>

#include "lab/eval/trajectory_evaluation.h"
#include "mlndt/common/result_table.h"

namespace mlndt {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

const ResultTable& AteSummaryTable() {
  using A = AteSummary;
  static const ResultTable table =
      ResultTableBuilder<A>("AteSummary")
          .Number("rmse_m", &A::rmse_m, "m", "RMSE of the position errors.")
          .Computed("mean_m",
                    ResultType::NUMBER,
                    "m",
                    "Mean position error (errors.mean).",
                    [](const A& a) { return ResultValue(a.errors.mean); })
          .Computed("median_m",
                    ResultType::NUMBER,
                    "m",
                    "Median position error (errors.median).",
                    [](const A& a) { return ResultValue(a.errors.median); })
          .Computed("max_m",
                    ResultType::NUMBER,
                    "m",
                    "Largest position error (errors.max).",
                    [](const A& a) { return ResultValue(a.errors.max); })
          .Computed("scale",
                    ResultType::NUMBER,
                    "",
                    "The alignment's scale (1 unless sim3).",
                    [](const A& a) {
                      return ResultValue(a.reference_from_estimate.scale);
                    })
          .Build();
  return table;
}

// A statistic of the RPE, NaN without a motion pair (fewer than delta + 1
// pose pairs).
ResultValue RpeValue(const RpeSummary& r, double value) {
  return ResultValue(r.translation_m.count > 0 ? value : kNan);
}

const ResultTable& RpeSummaryTable() {
  using R = RpeSummary;
  static const ResultTable table =
      ResultTableBuilder<R>("RpeSummary")
          .Computed(
              "pairs",
              ResultType::INTEGER,
              "",
              "Motions compared (pose pairs minus delta; 0: no RPE, "
              "the numbers below are NaN).",
              [](const R& r) {
                return ResultValue(static_cast<int64_t>(r.translation_m.count));
              })
          .Computed(
              "translation_rmse_m",
              ResultType::NUMBER,
              "m",
              "RMSE of the relative translation errors.",
              [](const R& r) { return RpeValue(r, r.translation_rmse_m); })
          .Computed(
              "translation_mean_m",
              ResultType::NUMBER,
              "m",
              "Their mean (translation_m.mean).",
              [](const R& r) { return RpeValue(r, r.translation_m.mean); })
          .Computed("translation_max_m",
                    ResultType::NUMBER,
                    "m",
                    "Their largest (translation_m.max).",
                    [](const R& r) { return RpeValue(r, r.translation_m.max); })
          .Computed("rotation_rmse_deg",
                    ResultType::NUMBER,
                    "deg",
                    "RMSE of the relative rotation errors.",
                    [](const R& r) { return RpeValue(r, r.rotation_rmse_deg); })
          .Computed("rotation_mean_deg",
                    ResultType::NUMBER,
                    "deg",
                    "Their mean (rotation_deg.mean).",
                    [](const R& r) { return RpeValue(r, r.rotation_deg.mean); })
          .Computed("rotation_max_deg",
                    ResultType::NUMBER,
                    "deg",
                    "Their largest (rotation_deg.max).",
                    [](const R& r) { return RpeValue(r, r.rotation_deg.max); })
          .Build();
  return table;
}

const ResultTable& KittiLengthErrorsTable() {
  using L = KittiLengthErrors;
  static const ResultTable table =
      ResultTableBuilder<L>("KittiLengthErrors")
          .Number("length_m", &L::length_m, "m", "The segment length.")
          .Integer("segments",
                   &L::num_segments,
                   "",
                   "Segments of this length (num_segments).")
          .Number("translation_error_percent",
                  &L::translation_error_percent,
                  "%",
                  "100 x their mean translation error [m/m].")
          .Number("rotation_error_deg_per_m",
                  &L::rotation_error_deg_per_m,
                  "deg/m",
                  "Their mean rotation error.")
          .Build();
  return table;
}

const ResultTable& KittiSegmentSummaryTable() {
  using K = KittiSegmentSummary;
  static const ResultTable table =
      ResultTableBuilder<K>("KittiSegmentSummary")
          .Computed(
              "segments",
              ResultType::INTEGER,
              "",
              "Segments evaluated, every length.",
              [](const K& k) {
                return ResultValue(static_cast<int64_t>(k.segments.size()));
              })
          .Number("translation_error_percent",
                  &K::translation_error_percent,
                  "%",
                  "Mean over all segments (the devkit's stats.txt, in %); "
                  "NaN without a segment.")
          .Number("rotation_error_deg_per_m",
                  &K::rotation_error_deg_per_m,
                  "deg/m",
                  "The same of the rotation errors.")
          .StructList("lengths",
                      &K::lengths,
                      KittiLengthErrorsTable(),
                      "Per length with at least one segment, in the "
                      "options' order.")
          .Build();
  return table;
}

}  // namespace

const ResultTable& TrajectoryEvaluationTable() {
  using S = TrajectoryEvaluation;
  static const ResultTable table =
      ResultTableBuilder<S>("TrajectoryEvaluation")
          .String("file", &S::file, "The estimate's file.")
          .Computed("format",
                    ResultType::STRING,
                    "",
                    "KITTI or TUM, as read.",
                    [](const S& s) {
                      return ResultValue(
                          std::string(TrajectoryFormatToString(s.format)));
                    })
          .String("association", &S::association, "index or timestamp.")
          .Integer("poses", &S::poses, "", "Poses of the estimate.")
          .Integer("pairs", &S::pairs, "", "Poses paired with the reference.")
          .Number("path_length_m",
                  &S::path_length_m,
                  "m",
                  "The reference's path length over the pairs.")
          .Struct("ate",
                  &S::ate,
                  AteSummaryTable(),
                  "The absolute trajectory error after the alignment.")
          .Struct("rpe",
                  &S::rpe,
                  RpeSummaryTable(),
                  "The relative pose error over delta poses.")
          .Struct("kitti",
                  &S::kitti,
                  KittiSegmentSummaryTable(),
                  "The KITTI devkit's segment errors.")
          .Build();
  return table;
}

}  // namespace mlndt
