#pragma once

// Registration of a scan sequence: scan i + step onto scan i for every i,
// with an initial-guess policy, optional ground truth and the paper's
// adaptive start layer (end of Section 5.3). Used by mlndt_sequence and
// mlndt_experiments.
//
// Adaptive start layer. The paper proposes: start on the last layer (the
// odometry is assumed good); a registration counts as failed when the
// estimate differs from the odometry guess by more than 1 m or 15 deg; once
// the fail rate passes 5 % start on a coarser layer, and past 20 % on a
// coarser one still. Here, precisely:
//  * the guess is the --init guess of the pair (the odometry stand-in);
//  * pair p (0-based) counts as failed when the registration reports
//    FAILURE, or TranslationErrorM(guess, estimate) > max_translation_m, or
//    RotationErrorRad(guess, estimate) > max_rotation_deg;
//  * the running fail rate before pair p is failed(0..p-1) / p (0 for p = 0),
//    i.e. cumulative over every pair so far, so it rises with failures and
//    decays as successes accumulate;
//  * pair p starts k layers coarser than the last layer, where k is the
//    number of thresholds (default 5 % and 20 %) the running rate exceeds
//    strictly: schedule.start_layer = -k (layer_scheduler.h: 0 = last
//    layer, -1 = one coarser, ...), clamped to layer 1 by the scheduler.
// With --init=zero the guess is no motion, so any true motion above 1 m
// counts as a failure: the rule assumes an odometry-like guess.

#include <functional>
#include <string>
#include <vector>

#include "mlndt/common/pose.h"
#include "mlndt/pipeline/matcher.h"
#include "tools/common/pair_evaluation.h"
#include "tools/common/scan_store.h"
#include "tools/common/tool_utils.h"

namespace mlndt {
namespace tools {

enum class InitMode {
  ZERO,         // Identity: no odometry (the paper's Z_i = 0).
  GT_FRACTION,  // c times the ground-truth motion (Z_i = c Z_gt, Table 9).
  CONSTANT_VELOCITY,  // The previous pair's estimate.
  POSES,              // Relative motion from a KITTI pose file (odometry).
};

struct InitSpec {
  InitMode mode = InitMode::ZERO;
  double fraction = 1.0;   // GT_FRACTION: c.
  std::string poses_path;  // POSES: the file.
};

// Parses "zero", "gt_fraction:c", "constant_velocity" or "poses:FILE".
inline bool ParseInitSpec(const std::string& text,
                          InitSpec* spec,
                          std::string* error) {
  *spec = InitSpec();
  if (text == "zero") return true;
  if (text == "constant_velocity") {
    spec->mode = InitMode::CONSTANT_VELOCITY;
    return true;
  }
  const std::string fraction_prefix = "gt_fraction:";
  if (text.rfind(fraction_prefix, 0) == 0) {
    std::vector<double> v;
    if (!ParseNumberList(text.substr(fraction_prefix.size()), &v) ||
        v.size() != 1) {
      *error = "--init=" + text +
               ": gt_fraction needs one number, e.g. gt_fraction:0.6";
      return false;
    }
    spec->mode = InitMode::GT_FRACTION;
    spec->fraction = v[0];
    return true;
  }
  const std::string poses_prefix = "poses:";
  if (text.rfind(poses_prefix, 0) == 0 && text.size() > poses_prefix.size()) {
    spec->mode = InitMode::POSES;
    spec->poses_path = text.substr(poses_prefix.size());
    return true;
  }
  *error = "--init=" + text +
           ": expected zero, gt_fraction:c, constant_velocity or poses:FILE";
  return false;
}

inline std::string InitSpecToString(const InitSpec& spec) {
  switch (spec.mode) {
    case InitMode::ZERO:
      return "zero";
    case InitMode::GT_FRACTION: {
      char text[64];
      std::snprintf(text, sizeof(text), "gt_fraction:%g", spec.fraction);
      return text;
    }
    case InitMode::CONSTANT_VELOCITY:
      return "constant_velocity";
    case InitMode::POSES:
      return "poses:" + spec.poses_path;
  }
  return "?";
}

// The adaptive start layer (see the top of this file).
struct AdaptiveStartLayerOptions {
  bool enabled = false;
  double max_translation_m =
      1.0;  // Deviation from the guess that counts as failed.
  double max_rotation_deg = 15.0;
  // Ascending fail rates in [0, 1]: exceeding the k-th starts k layers
  // coarser than the last.
  std::vector<double> fail_rate_thresholds = {0.05, 0.20};
};

struct SequenceOptions {
  MatcherOptions registration;
  size_t step = 1;  // Scan i + step is registered onto scan i. >= 1.
  InitSpec init;
  AdaptiveStartLayerOptions adaptive;
  // Free clouds and maps of scans no later pair needs (long sequences).
  bool release_used_scans = false;
};

struct PairResult {
  size_t reference = 0;
  size_t input = 0;
  Isometry3d guess = Isometry3d::Identity();  // Initial reference_from_input.
  Isometry3d estimate = Isometry3d::Identity();  // Registration result.
  bool has_truth = false;
  Isometry3d truth = Isometry3d::Identity();
  PoseError error;              // Valid when has_truth.
  bool success = false;         // Translation error < 0.5 m (has_truth).
  bool strict_success = false;  // < 0.2 m and < 1 deg (has_truth).
  TerminationType termination = TerminationType::FAILURE;
  std::string message;
  int iterations = 0;
  int start_layer = 0;  // 1-based layer the registration started on.
  int num_layers = 0;
  size_t sampled_points = 0;
  PairTimes times;
  // Distance of the estimate from the guess, and the adaptive rule's verdict.
  double guess_deviation_m = 0.0;
  double guess_deviation_deg = 0.0;
  bool guess_check_failed = false;
  double running_fail_rate = 0.0;  // Before this pair (adaptive rule).
  std::vector<IterationRecord> trace;
};

// Runs every pair (i, i + step). `truth` (world_from_scan per scan) and
// `odometry` (for InitMode::POSES) may be null; they must hold at least
// store->size() poses when given. `on_pair` (may be empty) is called after
// each pair with the number done and the total. False with *error on
// unreadable scans, unusable maps or missing poses.
inline bool RunSequence(
    const SequenceOptions& options,
    ScanStore* store,
    const std::vector<Isometry3d>* truth,
    const std::vector<Isometry3d>* odometry,
    const std::function<void(const PairResult&, size_t, size_t)>& on_pair,
    std::vector<PairResult>* results,
    std::string* error) {
  results->clear();
  const size_t n = store->size();
  if (options.step < 1) {
    *error = "step must be >= 1";
    return false;
  }
  if (truth != nullptr && truth->size() < n) {
    *error = "the ground truth has " + std::to_string(truth->size()) +
             " poses for " + std::to_string(n) + " scans";
    return false;
  }
  if (options.init.mode == InitMode::GT_FRACTION && truth == nullptr) {
    *error = "--init=gt_fraction needs ground-truth poses";
    return false;
  }
  if (options.init.mode == InitMode::POSES &&
      (odometry == nullptr || odometry->size() < n)) {
    *error = "--init=poses: the pose file needs one pose per scan (" +
             std::to_string(n) + ")";
    return false;
  }
  const size_t total = n > options.step ? n - options.step : 0;
  size_t failed_so_far = 0;
  Isometry3d previous_estimate = Isometry3d::Identity();
  for (size_t i = 0; i + options.step < n; ++i) {
    const size_t j = i + options.step;
    PairResult r;
    r.reference = i;
    r.input = j;
    if (truth != nullptr) {
      r.has_truth = true;
      r.truth = (*truth)[i].inverse() * (*truth)[j];
    }
    switch (options.init.mode) {
      case InitMode::ZERO:
        r.guess = Isometry3d::Identity();
        break;
      case InitMode::GT_FRACTION:
        r.guess = ScaleMotion(r.truth, options.init.fraction);
        break;
      case InitMode::CONSTANT_VELOCITY:
        r.guess = previous_estimate;
        break;
      case InitMode::POSES:
        r.guess = (*odometry)[i].inverse() * (*odometry)[j];
        break;
    }

    MatcherOptions registration = options.registration;
    if (options.adaptive.enabled) {
      r.running_fail_rate =
          results->empty() ? 0.0 : double(failed_so_far) / results->size();
      int coarser = 0;
      for (double threshold : options.adaptive.fail_rate_thresholds) {
        if (r.running_fail_rate > threshold) ++coarser;
      }
      registration.mlndt.schedule.start_layer = -coarser;
    }
    RegistrationSummary summary;
    if (!RegisterPair(
            registration, store, i, j, r.guess, &summary, &r.times, error))
      return false;

    r.termination = summary.termination_type;
    r.message = summary.message;
    // A FAILURE leaves no usable pose: the pair keeps its guess.
    r.estimate =
        summary.IsSolutionUsable() ? summary.reference_from_input : r.guess;
    r.iterations = summary.num_iterations;
    r.start_layer = summary.start_layer;
    r.num_layers = summary.num_layers;
    r.sampled_points = summary.sampled_points;
    r.trace = summary.trace;
    r.guess_deviation_m = TranslationErrorM(r.guess, r.estimate);
    r.guess_deviation_deg = RotationErrorRad(r.guess, r.estimate) * kRadToDeg;
    r.guess_check_failed =
        !summary.IsSolutionUsable() ||
        r.guess_deviation_m > options.adaptive.max_translation_m ||
        r.guess_deviation_deg > options.adaptive.max_rotation_deg;
    failed_so_far += r.guess_check_failed;
    if (r.has_truth) {
      r.error = ComputePoseError(r.truth, r.estimate);
      r.success = summary.IsSolutionUsable() &&
                  kPaperSuccessCriterion.IsWithin(r.error);
      r.strict_success =
          summary.IsSolutionUsable() && SuccessCriterion().IsWithin(r.error);
    }
    if (summary.IsSolutionUsable()) previous_estimate = r.estimate;
    results->push_back(std::move(r));
    if (options.release_used_scans) store->ReleaseBefore(i + 1);
    if (on_pair) on_pair(results->back(), results->size(), total);
  }
  return true;
}

// Chains the estimates of a sequence run into poses of scans 0, step,
// 2 step, ... relative to scan 0 (the first pose is the identity). Only
// pairs starting at a multiple of the step are chained.
inline std::vector<Isometry3d> ChainTrajectory(
    const std::vector<PairResult>& results, size_t step, bool use_truth) {
  std::vector<Isometry3d> poses = {Isometry3d::Identity()};
  for (const PairResult& r : results) {
    if (r.reference % step != 0) continue;
    poses.push_back(poses.back() * (use_truth ? r.truth : r.estimate));
  }
  return poses;
}

// Totals over a run, shared by summary.json and the experiment tables.
// Error statistics are over |component| (Tables 2-4 layout) in cm and deg.
struct SequenceTotals {
  size_t pairs = 0;
  bool has_truth = false;
  size_t successes = 0;              // < 0.5 m.
  size_t strict_successes = 0;       // < 0.2 m and < 1 deg.
  size_t registration_failures = 0;  // termination FAILURE.
  size_t guess_check_failures = 0;   // Adaptive rule's verdict.
  double success_rate_percent = 0.0;
  double strict_success_rate_percent = 0.0;
  // tx, ty, tz [cm], alpha, beta, gamma [deg], translation norm [cm],
  // rotation angle [deg]: over all pairs, and over successful pairs only.
  std::vector<Stats> errors = std::vector<Stats>(8);
  std::vector<Stats> errors_successful = std::vector<Stats>(8);
  Stats time_ms;  // Total per pair (map + registration).
  Stats map_time_ms;
  Stats registration_time_ms;  // Total minus map.
  Stats iterations;
};

inline const char* const* ErrorNames() {
  static const char* const kNames[8] = {"tx_cm",
                                        "ty_cm",
                                        "tz_cm",
                                        "alpha_deg",
                                        "beta_deg",
                                        "gamma_deg",
                                        "translation_cm",
                                        "rotation_deg"};
  return kNames;
}

// The 8 error values of a pair in report units (component magnitudes).
inline std::vector<double> ErrorValues(const PoseError& e) {
  std::vector<double> v(8);
  for (int k = 0; k < 3; ++k) v[k] = std::abs(e.components(k)) * 100.0;
  for (int k = 3; k < 6; ++k) v[k] = std::abs(e.components(k)) * kRadToDeg;
  v[6] = e.translation_m * 100.0;
  v[7] = e.rotation_rad * kRadToDeg;
  return v;
}

inline SequenceTotals ComputeTotals(const std::vector<PairResult>& results) {
  SequenceTotals t;
  t.pairs = results.size();
  t.has_truth = !results.empty() && results.front().has_truth;
  std::vector<std::vector<double>> errors(8), errors_successful(8);
  std::vector<double> time, map, registration, iterations;
  for (const PairResult& r : results) {
    t.registration_failures += r.termination == TerminationType::FAILURE;
    t.guess_check_failures += r.guess_check_failed;
    time.push_back(r.times.total_ms);
    map.push_back(r.times.map_ms);
    registration.push_back(r.times.total_ms - r.times.map_ms);
    iterations.push_back(r.iterations);
    if (!r.has_truth) continue;
    t.successes += r.success;
    t.strict_successes += r.strict_success;
    const std::vector<double> v = ErrorValues(r.error);
    for (int k = 0; k < 8; ++k) {
      errors[k].push_back(v[k]);
      if (r.success) errors_successful[k].push_back(v[k]);
    }
  }
  if (t.pairs > 0 && t.has_truth) {
    t.success_rate_percent = 100.0 * t.successes / t.pairs;
    t.strict_success_rate_percent = 100.0 * t.strict_successes / t.pairs;
  }
  for (int k = 0; k < 8; ++k) {
    t.errors[k] = ComputeStats(errors[k]);
    t.errors_successful[k] = ComputeStats(errors_successful[k]);
  }
  t.time_ms = ComputeStats(time);
  t.map_time_ms = ComputeStats(map);
  t.registration_time_ms = ComputeStats(registration);
  t.iterations = ComputeStats(iterations);
  return t;
}

}  // namespace tools
}  // namespace mlndt
