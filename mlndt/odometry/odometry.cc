#include "mlndt/odometry/odometry.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include "mlndt/common/pose.h"
#include "mlndt/common/timer.h"
#include "mlndt/odometry/confirm_pose.h"
#include "mlndt/odometry/deskew.h"
#include "mlndt/odometry/last_scan_check.h"
#include "mlndt/registration/registration.h"

namespace mlndt {
namespace {

bool CheckScan(const OdometryScan& scan,
               size_t num_processed,
               double last_stamp_s,
               std::string* error) {
  if (scan.cloud == nullptr || scan.cloud->empty()) {
    *error = "scan " + std::to_string(num_processed) + ": no points";
    return false;
  }
  if (!std::isfinite(scan.stamp_s) ||
      (num_processed > 0 && !(scan.stamp_s > last_stamp_s))) {
    std::ostringstream message;
    message.precision(17);
    message << "scan " << num_processed << ": time stamp " << scan.stamp_s
            << " is not after the previous scan's " << last_stamp_s;
    *error = message.str();
    return false;
  }
  if (scan.point_times_s != nullptr && !scan.point_times_s->empty() &&
      scan.point_times_s->size() != scan.cloud->size()) {
    *error = "scan " + std::to_string(num_processed) + ": " +
             std::to_string(scan.point_times_s->size()) + " point times for " +
             std::to_string(scan.cloud->size()) + " points";
    return false;
  }
  return true;
}

}  // namespace

void OdometrySummary::Add(const OdometryResult& result) {
  ++scans;
  switch (result.termination) {
    case TerminationType::CONVERGENCE:
      ++convergence;
      break;
    case TerminationType::NO_CONVERGENCE:
      ++no_convergence;
      break;
    case TerminationType::LOW_QUALITY:
      ++low_quality;
      break;
    case TerminationType::DEGENERATE:
      ++degenerate;
      break;
    case TerminationType::FAILURE:
      ++failure;
      break;
  }
  fallbacks += result.fallback;
  keyframes += result.keyframe;
  map_restarts += result.map_restarted;
}

Odometry::Odometry(const OdometryOptions& options)
    : options_(options),
      predictor_(options.prediction),
      local_map_(options.local_map),
      last_scan_map_(options.local_map) {
  std::string error;
  CHECK(options_.IsValid(&error)) << error;
}

// Registers onto the local map from the prediction and applies the gate.
void Odometry::Register(const PointCloud& cloud, OdometryResult* result) {
  RegistrationOptions options = options_.registration;
  options.initial_uncertainty.given = true;
  options.initial_uncertainty.translation_m = result->uncertainty.translation_m;
  options.initial_uncertainty.rotation_deg = result->uncertainty.rotation_deg;
  options.quality_check.max_flatness = options_.max_flatness;
  options.retry.weak_direction_rounds = options_.weak_direction_rounds;
  options.quality_check.max_mean_score = options_.max_mean_score;
  RegistrationSummary summary;
  mlndt::Register(
      options, local_map_.grid(), cloud, result->predicted, &summary);
  result->termination = summary.termination_type;
  result->message = summary.message;
  result->start_layer = summary.start_layer;
  result->num_layers = summary.num_layers;
  result->iterations = summary.num_iterations;
  result->sampled_points = summary.sampled_points;
  result->quality = summary.quality;
  result->registration_time_s = summary.total_time_s;
  result->world_from_sensor = summary.reference_from_input;
  result->correction_m =
      TranslationErrorM(result->predicted, summary.reference_from_input);
  result->correction_deg =
      RotationErrorRad(result->predicted, summary.reference_from_input) *
      kRadToDeg;
  // The gate: gate_factor x the uncertainty, at most the largest
  // uncertainty the prediction can have.
  const double gate_m =
      std::min(options_.gate_factor * result->uncertainty.translation_m,
               options_.prediction.max_translation_m);
  const double gate_deg =
      std::min(options_.gate_factor * result->uncertainty.rotation_deg,
               options_.prediction.max_rotation_deg);
  if (summary.IsSolutionUsable() &&
      (result->correction_m > gate_m || result->correction_deg > gate_deg)) {
    std::ostringstream message;
    message.precision(3);
    message << "the pose moved " << result->correction_m << " m, "
            << result->correction_deg << " deg from the prediction, beyond "
            << "the gate (" << gate_m << " m, " << gate_deg << " deg)";
    result->termination = TerminationType::LOW_QUALITY;
    result->message = message.str();
  }
  result->fallback = result->termination != TerminationType::CONVERGENCE &&
                     result->termination != TerminationType::NO_CONVERGENCE;
  if (result->fallback) result->world_from_sensor = result->predicted;
  if (result->termination == TerminationType::CONVERGENCE) {
    Confirm(options, cloud, result);
  }
}

// CONVERGENCE only for a pose the registration returns to (confirm_pose.h);
// an unconfirmed pose is kept, reported NO_CONVERGENCE.
void Odometry::Confirm(const RegistrationOptions& options,
                       const PointCloud& cloud,
                       OdometryResult* result) {
  if (!NeedsConfirmation(options_.confirmation,
                         options_.prediction,
                         result->uncertainty,
                         result->predicted,
                         result->world_from_sensor)) {
    return;
  }
  const Confirmation confirmation = ConfirmPose(options,
                                                options_.prediction,
                                                local_map_.grid(),
                                                cloud,
                                                result->uncertainty,
                                                result->predicted,
                                                result->world_from_sensor);
  result->registration_time_s += confirmation.time_s;
  if (!confirmation.confirmed) {
    result->termination = TerminationType::NO_CONVERGENCE;
    result->message += "; " + confirmation.message;
    return;
  }
  if (options_.confirmation.check_last_scan) {
    AgreesWithLastScan(options, cloud, result);
  }
}

// A pose the second run returned to must agree with the scan registered
// onto the last registered scan alone (last_scan_check.h); else
// NO_CONVERGENCE, the pose kept.
void Odometry::AgreesWithLastScan(const RegistrationOptions& options,
                                  const PointCloud& cloud,
                                  OdometryResult* result) {
  if (!has_last_scan_) return;
  if (!last_scan_map_built_) {
    std::string map_error;
    last_scan_map_.Clear();
    if (!last_scan_map_.AddKeyframe(last_scan_,
                                    last_scan_pose_,
                                    options_.registration.num_threads,
                                    &map_error)) {
      return;  // No map, no evidence.
    }
    last_scan_map_built_ = true;
  }
  const Confirmation check = CheckAgainstLastScan(options,
                                                  options_.prediction,
                                                  last_scan_map_.grid(),
                                                  cloud,
                                                  result->predicted,
                                                  result->world_from_sensor);
  result->registration_time_s += check.time_s;
  if (check.confirmed) return;
  result->termination = TerminationType::NO_CONVERGENCE;
  result->message += "; " + check.message;
}

bool Odometry::UpdateMap(const PointCloud& cloud,
                         OdometryResult* result,
                         std::string* error) {
  const bool first = local_map_.empty();
  if (!first &&
      (result->fallback || !IsNewKeyframe(options_.keyframes,
                                          local_map_.last_keyframe(),
                                          result->world_from_sensor))) {
    return true;
  }
  std::string map_error;
  if (!local_map_.AddKeyframe(cloud,
                              result->world_from_sensor,
                              options_.registration.num_threads,
                              &map_error)) {
    if (first) {
      *error = map_error;
      return false;
    }
    // The previous map stays; the scan is not a keyframe.
    result->message += (result->message.empty() ? "" : "; ") + map_error;
    return true;
  }
  result->keyframe = true;
  result->map_time_s = local_map_.build_time_s();
  return true;
}

bool Odometry::Process(const OdometryScan& scan,
                       OdometryResult* result,
                       std::string* error) {
  CHECK(result != nullptr);
  CHECK(error != nullptr);
  if (!CheckScan(scan, num_processed_, last_stamp_s_, error)) return false;
  const double start = NowSeconds();
  *result = OdometryResult();
  result->index = num_processed_;
  result->stamp_s = scan.stamp_s;
  result->predicted = predictor_.Predict(scan.stamp_s);
  result->uncertainty = predictor_.Uncertainty();

  PointCloud cloud = *scan.cloud;
  const bool has_times =
      scan.point_times_s != nullptr && !scan.point_times_s->empty();
  if (options_.deskew && has_times && predictor_.num_poses() >= 2) {
    if (!DeskewScan(predictor_.Velocity(), *scan.point_times_s, &cloud, error))
      return false;
    result->deskewed = true;
  }
  if (consecutive_fallbacks_ >=
      static_cast<size_t>(options_.max_consecutive_fallbacks)) {
    local_map_.Clear();
    result->map_restarted = true;
    result->fallback = true;
    result->termination = TerminationType::FAILURE;
    result->message = "no pose for " + std::to_string(consecutive_fallbacks_) +
                      " scans: the local map restarts from this scan, at "
                      "its prediction";
    result->world_from_sensor = result->predicted;
  } else if (local_map_.empty()) {
    result->termination = TerminationType::CONVERGENCE;
    result->message = "first scan: the origin of the odometry frame";
    result->world_from_sensor = result->predicted;
  } else {
    Register(cloud, result);
  }
  if (!UpdateMap(cloud, result, error)) return false;
  if (result->map_restarted || !result->fallback) {
    consecutive_fallbacks_ = 0;
    last_scan_ = std::move(cloud);
    last_scan_pose_ = result->world_from_sensor;
    has_last_scan_ = true;
    last_scan_map_built_ = false;
  } else {
    ++consecutive_fallbacks_;
  }
  if (result->fallback) {
    predictor_.AddPrediction(scan.stamp_s, result->predicted);
  } else {
    predictor_.AddPose(
        scan.stamp_s, result->predicted, result->world_from_sensor);
  }
  result->map_keyframes = local_map_.num_keyframes();
  result->map_points = local_map_.num_points();
  result->total_time_s = NowSeconds() - start;
  last_stamp_s_ = scan.stamp_s;
  ++num_processed_;
  return true;
}

}  // namespace mlndt
