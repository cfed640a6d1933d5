#pragma once

// Scan-to-local-map LiDAR odometry with ML-NDT:
//
//   Odometry odometry(options);
//   for (each scan) {
//     OdometryResult result;
//     odometry.Process({stamp_s, &cloud, &point_times_s}, &result);
//     if (!result.fallback) use(result.world_from_sensor);
//   }
//
// For each scan: predict its pose at its stamp with constant velocity
// (motion_prediction.h); deskew it when per-point times are given
// (deskew.h); register it onto the local map of recent keyframes
// (local_map.h) from the prediction, with the prediction's uncertainty as
// RegistrationOptions::initial_uncertainty (which picks the start layer,
// Section 5.3's guideline, and checks the result against a finest-layer run
// from the guess); accept the pose when the registration is usable and
// within gate_factor times that uncertainty of the prediction. Otherwise
// the prediction stands in for the pose, flagged (`fallback`), and the
// verdict says why. A CONVERGENCE with a large correction, or from a
// prediction at its largest uncertainty, stands only when a second
// registration from beyond the pose returns to it (confirm_pose.h) and the
// scan registered onto the last registered scan alone agrees
// (last_scan_check.h); else the pose is kept and reported NO_CONVERGENCE.
// Accepted scans that moved far enough (keyframe_policy.h) join the local map.
// The first scan defines the world frame (identity). After
// max_consecutive_fallbacks scans without a pose the local map restarts
// from the next scan, at its prediction.

#include <string>
#include <vector>

#include "mlndt/cloud/point_cloud.h"
#include "mlndt/common/types.h"
#include "mlndt/odometry/local_map.h"
#include "mlndt/odometry/motion_prediction.h"
#include "mlndt/odometry/odometry_options.h"
#include "mlndt/registration/registration_summary.h"

namespace mlndt {

// One scan: its time stamp [s] (strictly increasing), its points in the
// sensor frame and, optionally, one time per point relative to the stamp.
struct OdometryScan {
  double stamp_s = 0.0;
  const PointCloud* cloud = nullptr;
  const std::vector<double>* point_times_s = nullptr;  // May be null.
};

struct OdometryResult {
  size_t index = 0;
  double stamp_s = 0.0;
  Isometry3d predicted = Isometry3d::Identity();  // world_from_sensor.
  Isometry3d world_from_sensor = Isometry3d::Identity();
  PredictionUncertainty uncertainty;  // Of the prediction.
  // The registration's verdict, or LOW_QUALITY when the gate refused it.
  TerminationType termination = TerminationType::FAILURE;
  std::string message;
  // The prediction stands in for the pose (the verdict was not usable).
  bool fallback = false;
  bool keyframe = false;  // The scan joined the local map.
  // The local map was dropped before this scan (max_consecutive_fallbacks
  // scans without a pose) and restarted from it: its pose is the
  // prediction (a fallback) and the trajectory may jump here.
  bool map_restarted = false;
  bool deskewed = false;
  int start_layer = 0;
  int num_layers = 0;
  int iterations = 0;
  size_t sampled_points = 0;
  FitQuality quality;
  // Distance of the pose from the prediction.
  double correction_m = 0.0;
  double correction_deg = 0.0;
  size_t map_keyframes = 0;
  size_t map_points = 0;
  double registration_time_s = 0.0;
  double map_time_s = 0.0;  // Rebuilding the local map (keyframes).
  double total_time_s = 0.0;
};

// Counts of a run's verdicts.
struct OdometrySummary {
  size_t scans = 0;
  size_t convergence = 0;
  size_t no_convergence = 0;
  size_t low_quality = 0;
  size_t degenerate = 0;
  size_t failure = 0;
  size_t fallbacks = 0;
  size_t keyframes = 0;
  size_t map_restarts = 0;

  void Add(const OdometryResult& result);
  // Every scan got a pose from its registration.
  bool AllUsable() const { return fallbacks == 0; }
};

class Odometry {
 public:
  // CHECK-fails on invalid options (check options.IsValid first).
  explicit Odometry(const OdometryOptions& options);

  // Processes the next scan. False with *error on unusable input (a null or
  // empty cloud, a stamp not after the last one, point times that do not
  // match the points) or when the first scan's map cannot be built; the
  // state is then unchanged.
  bool Process(const OdometryScan& scan,
               OdometryResult* result,
               std::string* error);

  const LocalMap& local_map() const { return local_map_; }
  size_t num_processed() const { return num_processed_; }

 private:
  void Register(const PointCloud& cloud, OdometryResult* result);
  void Confirm(const RegistrationOptions& options,
               const PointCloud& cloud,
               OdometryResult* result);
  void AgreesWithLastScan(const RegistrationOptions& options,
                          const PointCloud& cloud,
                          OdometryResult* result);
  bool UpdateMap(const PointCloud& cloud,
                 OdometryResult* result,
                 std::string* error);

  OdometryOptions options_;
  MotionPredictor predictor_;
  LocalMap local_map_;
  size_t num_processed_ = 0;
  size_t consecutive_fallbacks_ = 0;
  double last_stamp_s_ = 0.0;
  // The last scan with a registered pose (or a restart scan), its pose and,
  // built when a confirmation needs it, its map (last_scan_check.h).
  PointCloud last_scan_;
  Isometry3d last_scan_pose_ = Isometry3d::Identity();
  bool has_last_scan_ = false;
  LocalMap last_scan_map_;
  bool last_scan_map_built_ = false;
};

}  // namespace mlndt
