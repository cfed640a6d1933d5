#include "mlndt/common/pose.h"
#include "mlndt/common/result_table.h"
#include "mlndt/pipeline/localizer.h"

namespace mlndt {
namespace {

using S = LocalizationResult;

ResultValue Matrix4(const Isometry3d& pose) {
  return ResultValue(Eigen::MatrixXd(pose.matrix()));
}

}  // namespace

const ResultTable& LocalizationResultTable() {
  static const ResultTable table =
      ResultTableBuilder<S>("LocalizationResult")
          .Integer("index",
                   &S::index,
                   "",
                   "0-based position of the scan in the sequence.")
          .Computed(
              "usable",
              ResultType::BOOL,
              "",
              "IsSolutionUsable(): the registration's verdict is "
              "CONVERGENCE or NO_CONVERGENCE.",
              [](const S& s) { return ResultValue(s.IsSolutionUsable()); })
          .Computed(
              "predicted_map_from_scan",
              ResultType::MATRIX,
              "m",
              "4x4 rigid transform (row-major): the prediction, the "
              "registration's initial guess.",
              [](const S& s) { return Matrix4(s.predicted_map_from_scan); })
          .Computed("map_from_scan",
                    ResultType::MATRIX,
                    "m",
                    "4x4 rigid transform (row-major): the estimate; the "
                    "prediction when the result is not usable.",
                    [](const S& s) { return Matrix4(s.map_from_scan); })
          .Computed("map_from_scan_xi",
                    ResultType::VECTOR,
                    "m, rad",
                    "The estimate as a pose vector (tx, ty, tz, alpha, beta, "
                    "gamma), Eq. 11.",
                    [](const S& s) {
                      return ResultValue(Eigen::VectorXd(
                          IsometryToPoseVector(s.map_from_scan)));
                    })
          .Computed("correction_m",
                    ResultType::NUMBER,
                    "m",
                    "Translation from the prediction to the estimate.",
                    [](const S& s) {
                      return ResultValue(TranslationErrorM(
                          s.predicted_map_from_scan, s.map_from_scan));
                    })
          .Computed("correction_rad",
                    ResultType::NUMBER,
                    "rad",
                    "Rotation angle from the prediction to the estimate.",
                    [](const S& s) {
                      return ResultValue(RotationErrorRad(
                          s.predicted_map_from_scan, s.map_from_scan));
                    })
          .Number("load_time_s", &S::load_time_s, "s", "Reading the scan.")
          .Struct("registration",
                  &S::registration,
                  RegistrationSummaryTable(),
                  "The registration of the scan onto the map from the "
                  "prediction (RegistrationSummary).")
          .Build();
  return table;
}

}  // namespace mlndt
