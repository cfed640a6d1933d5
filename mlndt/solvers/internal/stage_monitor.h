#pragma once

// Records the iterations of a hand-written minimiser's stage and decides
// convergence on the update norm, the way the Ceres backend's callback does.

#include "mlndt/common/timer.h"
#include "mlndt/solvers/backend.h"

namespace mlndt {
namespace internal {

class StageMonitor {
 public:
  StageMonitor(const StageControl& control, StageSummary* summary)
      : control_(control), summary_(summary), start_s_(NowSeconds()) {}

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
