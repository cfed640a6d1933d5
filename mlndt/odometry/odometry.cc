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
#include "mlndt/odometry/recovery.h"
#include "mlndt/registration/registration.h"

namespace mlndt {
namespace {

bool CheckScan(const OdometryScan& scan,
               size_t num_processed,
               double last_stamp_s,
               std::string* error) {
  if (scan.cloud == nullptr || (num_processed == 0 && scan.cloud->empty())) {
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

void AppendMessage(const std::string& text, std::string* message) {
  if (text.empty()) return;
  *message += (message->empty() ? "" : "; ") + text;
}

}  // namespace

void OdometrySummary::Add(const OdometryResult& result) {
  ++scans;
  switch (result.termination_type) {
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
  searched += result.search_starts > 0;
  recovered += result.recovered;
  interpolated += result.bridged.size();
}

Odometry::Odometry(const OdometryOptions& options)
    : options_(options),
      predictor_(options.prediction),
      local_map_(options.local_map),
      last_scan_map_(options.local_map) {
  std::string error;
  CHECK(options_.IsValid(&error)) << error;
}

RegistrationOptions Odometry::ScanRegistrationOptions(
    const PredictionUncertainty& uncertainty) const {
  RegistrationOptions options = options_.registration;
  options.initial_uncertainty.given = true;
  options.initial_uncertainty.translation_m = uncertainty.translation_m;
  options.initial_uncertainty.rotation_deg = uncertainty.rotation_deg;
  return options;
}

// Registers onto the local map from `start` and applies the verdict.
void Odometry::Register(const LayeredGrid& map,
                        PreparedRegistration* scan,
                        const Isometry3d& start,
                        bool always_confirm,
                        OdometryResult* result) {
  RegistrationSummary& summary = result->registration;
  scan->Register(map, start, &summary);
  result->termination_type = summary.termination_type;
  result->message = summary.message;
  result->registration_time_s += summary.total_time_s;
  result->world_from_sensor = summary.reference_from_input;
  result->correction_m = TranslationErrorM(result->predicted_world_from_sensor,
                                           summary.reference_from_input);
  result->correction_rad = RotationErrorRad(result->predicted_world_from_sensor,
                                            summary.reference_from_input);
  if (summary.IsSolutionUsable()) Gate(result);
  if (result->termination_type == TerminationType::CONVERGENCE) {
    Confirm(map, scan, start, always_confirm, result);
  }
}

// The gate: gate_factor x the uncertainty around the prediction, at most
// the largest uncertainty the prediction can have; beyond it LOW_QUALITY.
void Odometry::Gate(OdometryResult* result) const {
  // After skipped scans the caps grow by what the last velocity, times the
  // prediction's factor, covers in the time since the last registered scan
  // (once the velocity has been checked by a prediction: not at the start).
  double cap_m = options_.prediction.max_translation_m;
  double cap_deg = options_.prediction.max_rotation_deg;
  if (result->skipped_scans > 0 && predictor_.knows_model_errors()) {
    const double gap_s = result->stamp_s - predictor_.last_stamp_s();
    const Vector6d v = predictor_.Velocity() * options_.prediction.factor;
    cap_m += v.head<3>().norm() * gap_s;
    cap_deg = std::min(cap_deg + v.tail<3>().norm() * kRadToDeg * gap_s, 180.0);
  }
  const double gate_m =
      std::min(options_.gate_factor * result->uncertainty.translation_m, cap_m);
  const double gate_deg = std::min(
      options_.gate_factor * result->uncertainty.rotation_deg, cap_deg);
  const double correction_deg = result->correction_rad * kRadToDeg;
  if (result->correction_m <= gate_m && correction_deg <= gate_deg) {
    return;
  }
  // After a gap the sensor may have kept moving: the dead-reckoned pose is
  // as good a centre.
  if (TranslationErrorM(result->dead_reckoned_world_from_sensor,
                        result->world_from_sensor) <= gate_m &&
      RotationErrorRad(result->dead_reckoned_world_from_sensor,
                       result->world_from_sensor) *
              kRadToDeg <=
          gate_deg) {
    return;
  }
  std::ostringstream message;
  message.precision(3);
  message << "the pose moved " << result->correction_m << " m, "
          << correction_deg << " deg from the prediction, beyond "
          << "the gate (" << gate_m << " m, " << gate_deg << " deg)";
  result->termination_type = TerminationType::LOW_QUALITY;
  result->message = message.str();
}

// Registers a scan the prediction did not register from wider starts
// (recovery.h); the first whose verdict is CONVERGENCE (always confirmed)
// registers it. Otherwise the first attempt's verdict stands.
void Odometry::Search(PreparedRegistration* scan, OdometryResult* result) {
  std::vector<Isometry3d> starts = SearchStarts(
      options_.recovery,
      result->predicted_world_from_sensor,
      predictor_.num_poses() > 0 ? predictor_.last_pose()
                                 : result->predicted_world_from_sensor);
  if (result->skipped_scans > 0 && options_.recovery.max_search_starts > 0) {
    starts.insert(starts.begin(), result->dead_reckoned_world_from_sensor);
  }

  for (size_t k = 0; k < starts.size(); ++k) {
    OdometryResult attempt = *result;
    Register(local_map_.grid(), scan, starts[k], true, &attempt);
    result->registration_time_s = attempt.registration_time_s;
    ++result->search_starts;
    if (attempt.termination_type != TerminationType::CONVERGENCE) continue;
    const std::string first_message = result->message;
    const int tried = result->search_starts;
    *result = attempt;
    result->search_starts = tried;
    result->recovered = true;
    result->message = "registered from search start " + std::to_string(k) +
                      " (from the prediction: " + first_message + ")";
    return;
  }
  if (options_.recovery.register_onto_last_scan && BuildLastScanMap()) {
    OdometryResult attempt = *result;
    Register(last_scan_map_.grid(),
             scan,
             result->predicted_world_from_sensor,
             true,
             &attempt);
    result->registration_time_s = attempt.registration_time_s;
    ++result->search_starts;
    if (attempt.termination_type == TerminationType::CONVERGENCE &&
        AgreesWithLocalMap(scan, &attempt)) {
      const std::string first_message = result->message;
      const int tried = result->search_starts;
      *result = attempt;
      result->search_starts = tried;
      result->recovered = true;
      result->message =
          "registered onto the last registered scan alone (from "
          "the prediction onto the map: " +
          first_message + ")";
      return;
    }
  }
  if (result->search_starts > 0) {
    AppendMessage("no CONVERGENCE from " +
                      std::to_string(result->search_starts) + " search starts",
                  &result->message);
  }
}

// A pose found on the last registered scan alone must agree with the scan
// registered onto the local map from it (the last-scan check the other way
// round): that registration usable and within the prediction's smallest
// uncertainty of the pose.
bool Odometry::AgreesWithLocalMap(PreparedRegistration* scan,
                                  OdometryResult* result) {
  RegistrationSummary summary;
  scan->Register(local_map_.grid(), result->world_from_sensor, &summary);
  result->registration_time_s += summary.total_time_s;
  if (!summary.IsSolutionUsable()) return false;
  return TranslationErrorM(summary.reference_from_input,
                           result->world_from_sensor) <=
             options_.prediction.min_translation_m &&
         RotationErrorRad(summary.reference_from_input,
                          result->world_from_sensor) *
                 kRadToDeg <=
             options_.prediction.min_rotation_deg;
}

// The map of the last registered scan alone (built once per scan).
bool Odometry::BuildLastScanMap() {
  if (!has_last_scan_) return false;
  if (last_scan_map_built_) return true;
  std::string map_error;
  last_scan_map_.Clear();
  last_scan_map_built_ =
      last_scan_map_.AddKeyframe(last_scan_,
                                 last_scan_pose_,
                                 options_.registration.num_threads,
                                 &map_error);
  return last_scan_map_built_;
}

// CONVERGENCE only for a pose the registration returns to (confirm_pose.h);
// an unconfirmed pose is NO_CONVERGENCE.
void Odometry::Confirm(const LayeredGrid& map,
                       PreparedRegistration* scan,
                       const Isometry3d& start,
                       bool always_confirm,
                       OdometryResult* result) {
  if (!always_confirm && !NeedsConfirmation(options_.confirmation,
                                            options_.prediction,
                                            result->uncertainty,
                                            start,
                                            result->world_from_sensor)) {
    return;
  }
  if (!options_.confirmation.enabled) return;
  const Confirmation confirmation = ConfirmPose(options_.prediction,
                                                map,
                                                scan,
                                                result->uncertainty,
                                                start,
                                                result->world_from_sensor);
  result->registration_time_s += confirmation.time_s;
  // Onto the last registered scan itself, the last-scan check has no second
  // view to offer.
  const bool second_view = &map != &last_scan_map_.grid();
  if (!confirmation.confirmed) {
    if (second_view && options_.confirmation.last_scan_confirms &&
        AgreesWithLastScan(scan, result).agreed) {
      AppendMessage("confirmed by the last registered scan alone",
                    &result->message);
      return;
    }
    result->termination_type = TerminationType::NO_CONVERGENCE;
    AppendMessage(confirmation.message, &result->message);
    return;
  }
  if (!second_view || !options_.confirmation.check_last_scan) return;
  const Confirmation check = AgreesWithLastScan(scan, result);
  if (check.confirmed) return;
  result->termination_type = TerminationType::NO_CONVERGENCE;
  AppendMessage(check.message, &result->message);
}

// The scan registered onto the last registered scan alone, compared with
// its pose (last_scan_check.h); not run (confirmed, not agreed) without a
// last scan or its map.
Confirmation Odometry::AgreesWithLastScan(PreparedRegistration* scan,
                                          OdometryResult* result) {
  if (!BuildLastScanMap()) return Confirmation();  // No evidence.
  const Confirmation check =
      CheckAgainstLastScan(options_.prediction,
                           last_scan_map_.grid(),
                           scan,
                           result->predicted_world_from_sensor,
                           result->world_from_sensor);
  result->registration_time_s += check.time_s;
  return check;
}

bool Odometry::UpdateMap(const PointCloud& cloud,
                         OdometryResult* result,
                         std::string* error) {
  const bool first = local_map_.empty();
  if (!first && !IsNewKeyframe(options_.keyframes,
                               local_map_.last_keyframe(),
                               result->world_from_sensor)) {
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
    AppendMessage(map_error, &result->message);
    return true;
  }
  result->keyframe = true;
  result->map_time_s = local_map_.build_time_s();
  return true;
}

// The unregistered scans since the last registered one, interpolated
// between it and this one (recovery.h).
void Odometry::Bridge(OdometryResult* result) {
  for (const auto& [index, stamp_s] : unregistered_) {
    result->bridged.push_back({index,
                               InterpolatePose(predictor_.last_pose(),
                                               predictor_.last_stamp_s(),
                                               result->world_from_sensor,
                                               result->stamp_s,
                                               stamp_s)});
  }
  unregistered_.clear();
}

// The state after the scan: a registered scan bridges the gap before it,
// becomes the last registered scan and a pose of the prediction; an
// unregistered one waits for the next registered scan.
void Odometry::Account(PointCloud cloud,
                       const OdometryScan& scan,
                       OdometryResult* result) {
  if (result->fallback) {
    unregistered_.emplace_back(result->index, scan.stamp_s);
    predictor_.SkipScan();
    return;
  }
  if (predictor_.num_poses() > 0) Bridge(result);
  last_scan_ = std::move(cloud);
  last_scan_pose_ = result->world_from_sensor;
  has_last_scan_ = true;
  last_scan_map_built_ = false;
  predictor_.AddPose(scan.stamp_s,
                     result->predicted_world_from_sensor,
                     result->world_from_sensor);
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
  result->predicted_world_from_sensor = predictor_.Predict(scan.stamp_s);
  result->uncertainty = predictor_.Uncertainty();
  result->skipped_scans = predictor_.skipped();
  result->dead_reckoned_world_from_sensor = predictor_.DeadReckon(scan.stamp_s);

  PointCloud cloud = *scan.cloud;
  const bool has_times =
      scan.point_times_s != nullptr && !scan.point_times_s->empty();
  size_t untimed = 0;
  if (options_.deskew && has_times && predictor_.num_poses() >= 2) {
    if (!DeskewScan(predictor_.Velocity(),
                    *scan.point_times_s,
                    &cloud,
                    error,
                    &untimed)) {
      return false;
    }
    result->deskewed = true;
  }
  if (local_map_.empty()) {
    result->termination_type = TerminationType::CONVERGENCE;
    result->message = "first scan: the origin of the odometry frame";
    result->world_from_sensor = result->predicted_world_from_sensor;
  } else if (cloud.empty()) {
    result->termination_type = TerminationType::FAILURE;
    result->message = "no points";
  } else {
    // Every registration of the scan (the search's, the confirmation's)
    // samples the same points with the same options: the scan is filtered
    // and sampled once, and the solver set up once.
    const double prepare_start_s = NowSeconds();
    PreparedInput input;
    PrepareInput(options_.registration, cloud, &input);
    PreparedRegistration scan_registration(
        ScanRegistrationOptions(result->uncertainty), input);
    result->registration_time_s += NowSeconds() - prepare_start_s;
    Register(local_map_.grid(),
             &scan_registration,
             result->predicted_world_from_sensor,
             false,
             result);
    if (result->termination_type != TerminationType::CONVERGENCE) {
      Search(&scan_registration, result);
    }
  }
  if (untimed > 0) {
    AppendMessage(std::to_string(untimed) +
                      " point(s) without a finite time removed by deskewing",
                  &result->message);
  }
  result->fallback = result->termination_type != TerminationType::CONVERGENCE;
  if (result->fallback) {
    result->world_from_sensor = result->predicted_world_from_sensor;
  } else if (!UpdateMap(cloud, result, error)) {
    return false;
  }
  Account(std::move(cloud), scan, result);
  result->map_keyframes = local_map_.num_keyframes();
  result->map_points = local_map_.num_points();
  result->total_time_s = NowSeconds() - start;
  last_stamp_s_ = scan.stamp_s;
  ++num_processed_;
  return true;
}

}  // namespace mlndt
