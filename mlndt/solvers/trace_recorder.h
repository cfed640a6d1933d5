#pragma once

// Appends IterationRecords for the hand-written minimisers and decides
// convergence on the update norm, the way the Ceres backend's callback does.

#include "mlndt/common/timer.h"
#include "mlndt/solvers/backend.h"

namespace mlndt {

class TraceRecorder {
 public:
  TraceRecorder(const StageOptions& options, StageSummary* summary)
      : options_(options), summary_(summary) {}

  // Records one iteration; returns true when it converged the stage.
  bool Record(double score,
              double step_norm,
              bool successful,
              const Vector6d& xi) {
    IterationRecord record;
    record.layer = options_.layer;
    record.iteration =
        options_.first_iteration + static_cast<int>(summary_->trace.size());
    record.score = score;
    record.step_norm = step_norm;
    record.step_is_successful = successful;
    record.reference_from_input_xi = xi;
    record.time_s = NowSeconds() - options_.start_time_s;
    summary_->trace.push_back(record);
    summary_->iterations = static_cast<int>(summary_->trace.size());
    return options_.step_tolerance > 0.0 && successful &&
           step_norm < options_.step_tolerance;
  }

 private:
  const StageOptions& options_;
  StageSummary* summary_;
};

}  // namespace mlndt
