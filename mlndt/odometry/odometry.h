#pragma once

// Scan-to-local-map LiDAR odometry with ML-NDT:
//
//   Odometry odometry(options);
//   for (each scan) {
//     OdometryResult result;
//     odometry.Process({stamp_s, &cloud, &point_times_s}, &result);
//     for (const BridgedScan& b : result.bridged) replace(b.index, b.pose);
//     if (!result.fallback) use(result.world_from_sensor);
//   }
//
// For each scan: predict its pose at its stamp with constant velocity from
// the last registered scan (motion_prediction.h); deskew it when per-point
// times are given (deskew.h); register it onto the local map of recent
// keyframes (local_map.h) from the prediction, with the prediction's
// uncertainty as RegistrationOptions::initial_uncertainty (which picks the
// start layer, Section 5.3's guideline, and checks the result against a
// finest-layer run from the guess); accept the pose when the registration
// is usable and within gate_factor times that uncertainty of the
// prediction. A CONVERGENCE with a large correction, or from a prediction at
// its largest uncertainty, stands only when a second registration from
// beyond the pose returns to it (confirm_pose.h) and the scan registered
// onto the last registered scan alone agrees (last_scan_check.h); else it
// is NO_CONVERGENCE. Only CONVERGENCE registers a scan.
//
// A scan not registered from its prediction is registered again from wider
// starts (recovery.h); the first start whose verdict is CONVERGENCE
// registers it (`recovered`). A scan that stays unregistered is flagged
// (`fallback`, its verdict says why), does not join the map, and its
// prediction stands in for its pose until the next registered scan, which
// reports the interpolated poses of the unregistered scans before it
// (`bridged`). The local map keeps what it held: the next scan is predicted
// from the last registered one with an uncertainty that grows with each
// skipped scan. Accepted scans that moved far enough (keyframe_policy.h)
// join the local map. The first scan defines the world frame (identity).

#include <string>
#include <utility>
#include <vector>

#include "mlndt/cloud/point_cloud.h"
#include "mlndt/common/types.h"
#include "mlndt/odometry/confirm_pose.h"
#include "mlndt/odometry/local_map.h"
#include "mlndt/odometry/motion_prediction.h"
#include "mlndt/odometry/odometry_options.h"
#include "mlndt/registration/prepared_registration.h"
#include "mlndt/registration/registration_summary.h"

namespace mlndt {

class ResultTable;

// One scan: its time stamp [s] (strictly increasing), its points in the
// sensor frame and, optionally, one time per point relative to the stamp.
struct OdometryScan {
  double stamp_s = 0.0;
  const PointCloud* cloud = nullptr;
  const std::vector<double>* point_times_s = nullptr;  // May be null.
};

// An earlier scan without a registered pose, and its pose interpolated
// between the registered scans before and after it.
struct BridgedScan {
  size_t index = 0;
  Isometry3d world_from_sensor = Isometry3d::Identity();
};

// One scan's odometry. The registration whose pose was used (from the
// prediction, or from the search start that registered the scan) is
// `registration`; the odometry's own verdict (`termination_type`, after the
// gate, the confirmation and the search) and pose (`world_from_sensor`, the
// prediction for a fallback) may differ from the registration's.
struct OdometryResult {
  size_t index = 0;  // 0-based position of the scan in the sequence.
  double stamp_s = 0.0;
  Isometry3d predicted_world_from_sensor = Isometry3d::Identity();
  // After skipped scans: the last velocity over the whole gap (the
  // prediction moves one step at most); else the prediction.
  Isometry3d dead_reckoned_world_from_sensor = Isometry3d::Identity();
  Isometry3d world_from_sensor = Isometry3d::Identity();
  PredictionUncertainty uncertainty;  // Of the prediction.
  // Scans without a registered pose since the last registered one.
  size_t skipped_scans = 0;
  // The odometry's verdict: the registration's, LOW_QUALITY when the gate
  // refused it, NO_CONVERGENCE when the confirmation did not return.
  TerminationType termination_type = TerminationType::FAILURE;
  std::string message;
  // Not registered (the verdict is not CONVERGENCE): the prediction stands
  // in for the pose, until a later registered scan bridges it.
  bool fallback = false;
  // Starts of the search tried (recovery.h), and whether one of them
  // registered the scan.
  int search_starts = 0;
  bool recovered = false;
  // A fallback whose pose a later scan replaced by the interpolated one
  // (set by whoever applies `bridged`, as RunOdometry does).
  bool interpolated = false;
  // Earlier fallbacks bridged by this scan's registration, oldest first.
  std::vector<BridgedScan> bridged;
  bool keyframe = false;  // The scan joined the local map.
  bool deskewed = false;
  // Distance of the registration's pose from the prediction.
  double correction_m = 0.0;
  double correction_rad = 0.0;
  size_t map_keyframes = 0;
  size_t map_points = 0;
  // Every registration of the scan (confirmations, search starts, checks).
  double registration_time_s = 0.0;
  double map_time_s = 0.0;  // Rebuilding the local map (keyframes).
  double total_time_s = 0.0;
  // The registration whose result was used (empty for the first scan and a
  // scan without points): start layer, iterations, fit, covariance, times.
  RegistrationSummary registration;
};

// OdometryResult's fields (result_table.h), the registration's table
// nested: mlndt_odometry's scans.csv/scans.json, Python's OdometryResult and
// docs/json_schema.md come from it.
const ResultTable& OdometryResultTable();

// Counts of a run's verdicts.
struct OdometrySummary {
  size_t scans = 0;
  size_t convergence = 0;
  size_t no_convergence = 0;
  size_t low_quality = 0;
  size_t degenerate = 0;
  size_t failure = 0;
  size_t fallbacks = 0;  // Scans without a registered pose.
  size_t keyframes = 0;
  size_t searched = 0;      // Scans the search ran on.
  size_t recovered = 0;     // ... and registered.
  size_t interpolated = 0;  // Fallbacks bridged by a later registered scan.

  void Add(const OdometryResult& result);
  // Every scan got a pose from its registration.
  bool AllUsable() const { return fallbacks == 0; }
};

class Odometry {
 public:
  // CHECK-fails on invalid options (check options.IsValid first).
  explicit Odometry(const OdometryOptions& options);

  // Processes the next scan. False with *error on unusable input (a null
  // cloud, a stamp not after the last one, point times that do not match
  // the points, an empty first scan) or when the first scan's map cannot be
  // built; the state is then unchanged. A later scan without points is a
  // FAILURE, a fallback like any scan not registered.
  bool Process(const OdometryScan& scan,
               OdometryResult* result,
               std::string* error);

  const LocalMap& local_map() const { return local_map_; }
  size_t num_processed() const { return num_processed_; }

 private:
  RegistrationOptions ScanRegistrationOptions(
      const PredictionUncertainty& uncertainty) const;
  // Registers the scan from `start` and applies the verdict (gate around
  // result->predicted, confirmation, last-scan check) into *result. `scan`:
  // the scan prepared once, with the scan's options (every registration of
  // it samples the same points and shares the solver's set-up).
  void Register(const LayeredGrid& map,
                PreparedRegistration* scan,
                const Isometry3d& start,
                bool always_confirm,
                OdometryResult* result);
  void Gate(OdometryResult* result) const;
  void Search(PreparedRegistration* scan, OdometryResult* result);
  bool BuildLastScanMap();
  bool AgreesWithLocalMap(PreparedRegistration* scan, OdometryResult* result);
  void Confirm(const LayeredGrid& map,
               PreparedRegistration* scan,
               const Isometry3d& start,
               bool always_confirm,
               OdometryResult* result);
  Confirmation AgreesWithLastScan(PreparedRegistration* scan,
                                  OdometryResult* result);
  bool UpdateMap(const PointCloud& cloud,
                 OdometryResult* result,
                 std::string* error);
  void Bridge(OdometryResult* result);
  void Account(PointCloud cloud, const OdometryScan& scan, OdometryResult* r);

  OdometryOptions options_;
  MotionPredictor predictor_;
  LocalMap local_map_;
  size_t num_processed_ = 0;
  double last_stamp_s_ = 0.0;
  // Scans without a registered pose since the last registered one: index
  // and stamp.
  std::vector<std::pair<size_t, double>> unregistered_;
  // The last scan with a registered pose, its pose and, built when a
  // confirmation needs it, its map (last_scan_check.h).
  PointCloud last_scan_;
  Isometry3d last_scan_pose_ = Isometry3d::Identity();
  bool has_last_scan_ = false;
  LocalMap last_scan_map_;
  bool last_scan_map_built_ = false;
};

}  // namespace mlndt
