#include "mlndt/schedule/layer_scheduler.h"

#include <glog/logging.h>

#include <algorithm>

#include "mlndt/common/check_option.h"

namespace mlndt {

bool LayerScheduleOptions::IsValid(std::string* error) const {
  MLNDT_OPTION_GE(iterations_per_layer, 1);
  MLNDT_OPTION_GE(max_final_iterations, 1);
  MLNDT_OPTION_GT(step_tolerance, 0.0);
  MLNDT_OPTION_GE(coarse_step_tolerance, 0.0);
  MLNDT_OPTION_GE(max_coarse_point_stride, 1);
  return true;
}

int ResolveStartLayer(const LayerScheduleOptions& options, int num_layers) {
  const int s = options.start_layer > 0 ? options.start_layer
                                        : num_layers + options.start_layer;
  return std::clamp(s, 1, num_layers);
}

void RunLayerSchedule(const LayerScheduleOptions& options,
                      const LayeredGrid& reference_map,
                      const std::vector<Eigen::Vector3d>& input_points,
                      const StageOptions& stage_options,
                      Backend* backend,
                      Vector6d* reference_from_input_xi,
                      ScheduleSummary* summary) {
  CHECK(backend != nullptr);
  CHECK(summary != nullptr);
  *summary = ScheduleSummary();
  const int n = reference_map.num_layers();
  summary->iterations_per_layer.assign(static_cast<size_t>(n), 0);
  for (int layer = ResolveStartLayer(options, n); layer <= n; ++layer) {
    const bool last = layer == n;
    StageOptions stage = stage_options;
    stage.layer = layer;
    stage.max_iterations =
        last ? options.max_final_iterations : options.iterations_per_layer;
    stage.step_tolerance =
        last ? options.step_tolerance : options.coarse_step_tolerance;
    stage.first_iteration = static_cast<int>(summary->trace.size()) + 1;
    // Coarse cells are large: every stride-th sample describes them as well.
    stage.point_stride =
        std::min(options.max_coarse_point_stride, 1 << std::min(20, n - layer));
    StageSummary stage_summary;
    backend->SolveStage(reference_map.layer(layer),
                        input_points,
                        stage,
                        reference_from_input_xi,
                        &stage_summary);
    summary->iterations_per_layer[static_cast<size_t>(layer - 1)] =
        stage_summary.iterations;
    summary->trace.insert(summary->trace.end(),
                          stage_summary.trace.begin(),
                          stage_summary.trace.end());
    if (stage_summary.termination_type == TerminationType::FAILURE) {
      summary->termination_type = TerminationType::FAILURE;
      summary->message =
          "layer " + std::to_string(layer) + ": " + stage_summary.message;
      return;
    }
    if (last) {
      summary->termination_type = stage_summary.termination_type;
      summary->message =
          stage_summary.termination_type == TerminationType::CONVERGENCE
              ? "converged on layer " + std::to_string(layer)
              : "iteration cap reached on layer " + std::to_string(layer) +
                    " (" + stage_summary.message + ")";
    }
  }
}

}  // namespace mlndt
