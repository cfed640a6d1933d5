#pragma once

// The stage of a hand-written minimiser (Newton, LM): starts its summary,
// records its iterations and decides convergence on the update norm, the way
// the Ceres backend's callback does, and ends it on the failures both share.

#include <string>

#include "mlndt/common/timer.h"
#include "mlndt/solvers/backend.h"

namespace mlndt {
namespace internal {

class StageMonitor {
 public:
  // Resets *summary: NO_CONVERGENCE "iteration cap reached" until an
  // iteration or a failure ends the stage.
  StageMonitor(const StageControl& control, StageSummary* summary)
      : control_(control), summary_(summary), start_s_(NowSeconds()) {
    *summary_ = StageSummary();
    summary_->termination_type = TerminationType::NO_CONVERGENCE;
    summary_->message = "iteration cap reached";
  }

  // Ends the stage: FAILURE with `message`.
  void Fail(const char* message) {
    summary_->termination_type = TerminationType::FAILURE;
    summary_->message = message;
  }
  // True, with the stage ended, when no point was scored (nothing to
  // minimise).
  bool FailIfUnmatched(size_t matched) {
    if (matched > 0) return false;
    Fail("no input point lies in an occupied cell");
    return true;
  }
  // True, with the stage ended ("the <method> step is not finite"), when
  // the solved step is not finite.
  bool FailIfNotFinite(const Vector6d& step, const char* method) {
    if (step.allFinite()) return false;
    summary_->termination_type = TerminationType::FAILURE;
    summary_->message = std::string("the ") + method + " step is not finite";
    return true;
  }

  // Records one iteration; returns true when it ends the stage (backend.h:
  // StageControl), with the summary's termination and message set.
  bool Record(double score,
              double step_norm,
              bool successful,
              const Vector6d& xi) {
    IterationRecord record;
    record.score = score;
    record.step_norm = step_norm;
    record.step_is_successful = successful;
    record.reference_from_input_xi = xi;
    record.time_s = NowSeconds() - start_s_;
    summary_->trace.push_back(record);
    const StageEnd end = control_.EndAfter(step_norm, successful);
    EndStage(end, summary_);
    return end != StageEnd::NONE;
  }

 private:
  const StageControl& control_;
  StageSummary* summary_;
  const double start_s_;
};

// Every stride-th point of `points`: `points` itself for stride 1, otherwise
// a copy in *storage.
inline const std::vector<Eigen::Vector3d>& EveryNthPoint(
    const std::vector<Eigen::Vector3d>& points,
    int stride,
    std::vector<Eigen::Vector3d>* storage) {
  if (stride <= 1) return points;
  storage->clear();
  storage->reserve(points.size() / static_cast<size_t>(stride) + 1);
  for (size_t i = 0; i < points.size(); i += static_cast<size_t>(stride)) {
    storage->push_back(points[i]);
  }
  return *storage;
}

}  // namespace internal
}  // namespace mlndt
