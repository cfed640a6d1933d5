#include "lab/runs/sequence_registration.h"

#include <glog/logging.h>

#include <cstdio>
#include <utility>

#include "lab/runs/sequence_option_table.h"
#include "mlndt/common/pose.h"

namespace mlndt {
namespace {

bool CheckInputs(const SequenceOptions& options,
                 size_t n,
                 const std::vector<Isometry3d>* truth,
                 const std::vector<Isometry3d>* odometry,
                 std::string* error) {
  if (!options.IsValid(error)) return false;
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
  return true;
}

// Scores a pair's registration (r->registration) against the guess and,
// when known, the truth.
void ScoreResult(const SequenceOptions& options, PairResult* r) {
  const bool usable = r->registration.IsSolutionUsable();
  r->estimate = usable ? r->registration.reference_from_input : r->guess;
  const GuessCheck check =
      CheckGuess(options.adaptive, usable, r->guess, r->estimate);
  r->guess_deviation_m = check.deviation_m;
  r->guess_deviation_deg = check.deviation_deg;
  r->guess_check_failed = check.failed;
  if (r->has_truth) {
    r->error = ComputePoseError(r->truth, r->estimate);
    r->success = usable && kPaperSuccessCriterion.IsWithin(r->error);
    r->strict_success = usable && SuccessCriterion().IsWithin(r->error);
  }
}

// The progress line of a pair: pair, verdict, iterations, time and, with
// truth, error ("pair 0->1 CONVERGENCE, 37 it, 338 ms, error 17.3 cm 0.20
// deg").
std::string StatusLine(const PairResult& r) {
  char line[160];
  int used =
      std::snprintf(line,
                    sizeof(line),
                    "pair %zu->%zu %s, %d it, %.0f ms",
                    r.reference,
                    r.input,
                    TerminationTypeToString(r.registration.termination_type),
                    r.registration.num_iterations,
                    r.times.total_ms);
  if (r.has_truth && used > 0 && used < static_cast<int>(sizeof(line))) {
    std::snprintf(line + used,
                  sizeof(line) - used,
                  ", error %.1f cm %.2f deg",
                  r.error.translation_m * 100.0,
                  r.error.rotation_rad * kRadToDeg);
  }
  return line;
}

}  // namespace

bool SequenceOptions::IsValid(std::string* error) const {
  return SequenceOwnOptionsTable().Check(*this, error) &&
         adaptive.IsValid(error);
}

bool RunSequence(const SequenceOptions& options,
                 ScanStore* store,
                 const std::vector<Isometry3d>* truth,
                 const std::vector<Isometry3d>* odometry,
                 ProgressCallback* progress,
                 std::vector<PairResult>* results,
                 std::string* error) {
  CHECK(store != nullptr);
  CHECK(results != nullptr);
  CHECK(error != nullptr);
  results->clear();
  const size_t n = store->size();
  if (!CheckInputs(options, n, truth, odometry, error)) return false;
  const size_t total = n > options.step ? n - options.step : 0;
  InitialGuessPolicy guesses(options.init);
  AdaptiveStartLayer adaptive(options.adaptive);
  for (size_t i = 0; i + options.step < n; ++i) {
    const size_t j = i + options.step;
    PairResult r;
    r.reference = i;
    r.input = j;
    if (truth != nullptr) {
      r.has_truth = true;
      r.truth = (*truth)[i].inverse() * (*truth)[j];
    }
    r.guess = guesses.Guess(r.truth,
                            options.init.mode == InitMode::POSES
                                ? (*odometry)[i].inverse() * (*odometry)[j]
                                : Isometry3d::Identity());
    MatcherOptions registration = options.registration;
    if (options.adaptive.enabled) {
      r.running_fail_rate = adaptive.running_fail_rate();
      registration.mlndt.schedule.start_layer = adaptive.StartLayer();
    }
    if (!RegisterPair(registration,
                      store,
                      i,
                      j,
                      r.guess,
                      &r.registration,
                      &r.times,
                      error)) {
      return false;
    }
    ScoreResult(options, &r);
    adaptive.Record(r.guess_check_failed);
    guesses.Record(r.registration.IsSolutionUsable(), r.estimate);
    results->push_back(std::move(r));
    if (options.release_used_scans) store->ReleaseBefore(i + 1);
    ReportProgress(progress,
                   {i, results->size(), total, StatusLine(results->back())});
  }
  return true;
}

std::vector<Isometry3d> ChainTrajectory(const std::vector<PairResult>& results,
                                        size_t step,
                                        bool use_truth) {
  std::vector<Isometry3d> poses = {Isometry3d::Identity()};
  for (const PairResult& r : results) {
    if (r.reference % step != 0) continue;
    poses.push_back(poses.back() * (use_truth ? r.truth : r.estimate));
  }
  return poses;
}

}  // namespace mlndt
