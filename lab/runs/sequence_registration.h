#pragma once

// Registration of a scan sequence: scan i + step onto scan i for every i,
// on maps the ScanStore builds once (Section 4.3), with an initial-guess
// policy (initial_guess.h), optional ground truth and the paper's adaptive
// start layer (adaptive_start_layer.h, which states the exact rule). Used by
// mlndt_sequence and mlndt_experiments.

#include <string>
#include <vector>

#include "lab/eval/pose_error.h"
#include "lab/runs/adaptive_start_layer.h"
#include "lab/runs/initial_guess.h"
#include "lab/runs/matcher.h"
#include "lab/runs/pair_registration.h"
#include "lab/runs/scan_store.h"
#include "mlndt/common/progress.h"

namespace mlndt {

struct SequenceOptions {
  MatcherOptions registration;
  size_t step = 1;  // Scan i + step is registered onto scan i. >= 1.
  InitSpec init;
  AdaptiveStartLayerOptions adaptive;
  // Free clouds and maps of scans no later pair needs (long sequences).
  bool release_used_scans = false;

  // step's range (SequenceOwnOptionsTable) and adaptive's IsValid; false
  // with *error naming the field.
  bool IsValid(std::string* error) const;
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
  // The registration's own summary (verdict, message, iterations, layers,
  // samples, trace); `estimate` is its pose only when that is usable.
  RegistrationSummary registration;
  PairTimes times;
  // Distance of the estimate from the guess, and the adaptive rule's verdict.
  double guess_deviation_m = 0.0;
  double guess_deviation_deg = 0.0;
  bool guess_check_failed = false;
  double running_fail_rate = 0.0;  // Before this pair (adaptive rule).
};

// Runs every pair (i, i + step). `truth` (world_from_scan per scan) and
// `odometry` (for InitMode::POSES) may be null; they must hold at least
// store->size() poses when given. `progress` (may be null, not owned) hears
// of each pair once it is registered: "pair 0->1 CONVERGENCE, 37 it, 338 ms"
// (and its error with truth). A FAILURE leaves
// no usable pose: the pair keeps its guess as its estimate. False with
// *error on unreadable scans, unusable maps or missing poses.
bool RunSequence(const SequenceOptions& options,
                 ScanStore* store,
                 const std::vector<Isometry3d>* truth,
                 const std::vector<Isometry3d>* odometry,
                 ProgressCallback* progress,
                 std::vector<PairResult>* results,
                 std::string* error);

// Chains the estimates of a sequence run into poses of scans 0, step,
// 2 step, ... relative to scan 0 (the first pose is the identity). Only
// pairs starting at a multiple of the step are chained.
std::vector<Isometry3d> ChainTrajectory(const std::vector<PairResult>& results,
                                        size_t step,
                                        bool use_truth);

}  // namespace mlndt
