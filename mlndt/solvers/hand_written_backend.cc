#include "mlndt/solvers/hand_written_backend.h"

#include <glog/logging.h>

#include "mlndt/solvers/internal/stage_monitor.h"

namespace mlndt {

void HandWrittenBackend::SetProblem(
    const std::vector<Eigen::Vector3d>& input_points,
    const ObjectiveOptions& objective,
    int num_threads) {
  input_points_ = &input_points;
  objective_ = objective;
  num_threads_ = num_threads;
}

void HandWrittenBackend::SolveStage(const NdtLayer& layer,
                                    const StageControl& control,
                                    Vector6d* reference_from_input_xi,
                                    StageSummary* summary) {
  CHECK(input_points_ != nullptr) << name_ << ": SetProblem first";
  std::vector<Eigen::Vector3d> thinned;
  const auto& points =
      internal::EveryNthPoint(*input_points_, control.point_stride, &thinned);
  Minimize(MlNdtObjective(layer, points, objective_, num_threads_),
           control,
           reference_from_input_xi,
           summary);
}

}  // namespace mlndt
