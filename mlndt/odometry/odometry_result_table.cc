#include "mlndt/common/pose.h"
#include "mlndt/common/result_table.h"
#include "mlndt/odometry/odometry.h"

namespace mlndt {
namespace {

using S = OdometryResult;

ResultValue Matrix4(const Isometry3d& pose) {
  return ResultValue(Eigen::MatrixXd(pose.matrix()));
}

const ResultTable& PredictionUncertaintyTable() {
  using U = PredictionUncertainty;
  static const ResultTable table =
      ResultTableBuilder<U>("PredictionUncertainty")
          .Number("translation_m",
                  &U::translation_m,
                  "m",
                  "Translation uncertainty of the prediction.")
          .Number("rotation_deg",
                  &U::rotation_deg,
                  "deg",
                  "Rotation uncertainty of the prediction.")
          .Build();
  return table;
}

const ResultTable& BridgedScanTable() {
  using B = BridgedScan;
  static const ResultTable table =
      ResultTableBuilder<B>("BridgedScan")
          .Integer("index", &B::index, "", "The earlier fallback's index.")
          .Computed("world_from_sensor",
                    ResultType::MATRIX,
                    "m",
                    "4x4 rigid transform (row-major): its pose interpolated "
                    "between the registered scans before and after it.",
                    [](const B& b) { return Matrix4(b.world_from_sensor); })
          .Build();
  return table;
}

// The poses of the scan: the prediction, the dead-reckoned one, the pose.
void AddPoses(ResultTableBuilder<S>* builder) {
  builder
      ->Computed(
          "predicted_world_from_sensor",
          ResultType::MATRIX,
          "m",
          "4x4 rigid transform (row-major): the constant-velocity "
          "prediction, the registration's initial guess.",
          [](const S& s) { return Matrix4(s.predicted_world_from_sensor); })
      .Computed(
          "dead_reckoned_world_from_sensor",
          ResultType::MATRIX,
          "m",
          "4x4 rigid transform (row-major): after skipped scans the "
          "last velocity over the whole gap; else the prediction.",
          [](const S& s) { return Matrix4(s.dead_reckoned_world_from_sensor); })
      .Computed("world_from_sensor",
                ResultType::MATRIX,
                "m",
                "4x4 rigid transform (row-major): the pose (the first scan "
                "defines the world); the prediction for a fallback.",
                [](const S& s) { return Matrix4(s.world_from_sensor); })
      .Computed("world_from_sensor_xi",
                ResultType::VECTOR,
                "m, rad",
                "The pose as a pose vector (tx, ty, tz, alpha, beta, gamma), "
                "Eq. 11.",
                [](const S& s) {
                  return ResultValue(Eigen::VectorXd(
                      IsometryToPoseVector(s.world_from_sensor)));
                })
      .Struct("uncertainty",
              &S::uncertainty,
              PredictionUncertaintyTable(),
              "The prediction's uncertainty (PredictionUncertainty).");
}

// What happened to the scan: verdict, search, bridging, map.
void AddOutcome(ResultTableBuilder<S>* builder) {
  builder
      ->Enum("termination_type",
             &S::termination_type,
             TerminationTypeTable(),
             "The odometry's verdict: the registration's, LOW_QUALITY when "
             "the gate refused it, NO_CONVERGENCE when the confirmation did "
             "not return.")
      .String("message", &S::message, "Why, in words.")
      .Bool("fallback",
            &S::fallback,
            "Not registered (the verdict is not CONVERGENCE): the prediction "
            "stands in for the pose.")
      .Integer("skipped_scans",
               &S::skipped_scans,
               "",
               "Scans without a registered pose since the last registered "
               "one.")
      .Integer("search_starts",
               &S::search_starts,
               "",
               "Starts of the search tried (the prediction did not register "
               "the scan).")
      .Bool("recovered", &S::recovered, "A search start registered the scan.")
      .Bool("interpolated",
            &S::interpolated,
            "A fallback whose pose a later registered scan replaced by the "
            "interpolated one.")
      .StructList("bridged",
                  &S::bridged,
                  BridgedScanTable(),
                  "Earlier fallbacks this scan's registration bridged, oldest "
                  "first (BridgedScan).")
      .Bool("keyframe", &S::keyframe, "The scan joined the local map.")
      .Bool("deskewed", &S::deskewed, "The scan was deskewed.");
}

}  // namespace

const ResultTable& OdometryResultTable() {
  static const ResultTable table = [] {
    ResultTableBuilder<S> builder("OdometryResult");
    builder
        .Integer("index",
                 &S::index,
                 "",
                 "0-based position of the scan in the sequence.")
        .Number("stamp_s", &S::stamp_s, "s", "The scan's time stamp.");
    AddOutcome(&builder);
    AddPoses(&builder);
    builder
        .Number("correction_m",
                &S::correction_m,
                "m",
                "Translation from the prediction to the registration's pose.")
        .Number("correction_rad",
                &S::correction_rad,
                "rad",
                "Rotation angle from the prediction to the registration's "
                "pose.")
        .Integer("map_keyframes",
                 &S::map_keyframes,
                 "",
                 "Keyframes in the local map after the scan.")
        .Integer("map_points",
                 &S::map_points,
                 "",
                 "Points in the local map after the scan.")
        .Number("registration_time_s",
                &S::registration_time_s,
                "s",
                "Every registration of the scan (confirmations, search "
                "starts, checks).")
        .Number("map_time_s",
                &S::map_time_s,
                "s",
                "Rebuilding the local map (keyframes).")
        .Number("total_time_s", &S::total_time_s, "s", "The whole scan.")
        .Struct("registration",
                &S::registration,
                RegistrationSummaryTable(),
                "The registration whose result was used (RegistrationSummary; "
                "empty for the first scan and a scan without points).");
    return builder.Build();
  }();
  return table;
}

}  // namespace mlndt
