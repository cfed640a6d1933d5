#include "mlndt/schedule/layer_scheduler.h"

#include <glog/logging.h>

#include <algorithm>

#include "mlndt/common/internal/check_option.h"
#include "mlndt/common/option_table.h"
#include "mlndt/common/timer.h"

namespace mlndt {
StageControl StageControlFor(const LayerScheduleOptions& options,
                             int layer,
                             int n) {
  const bool last = layer == n;
  StageControl control;
  control.max_iterations =
      last ? options.max_final_iterations : options.iterations_per_layer;
  control.step_tolerance =
      last ? options.step_tolerance : options.coarse_step_tolerance;
  control.end_on_rejected_step =
      !last && options.end_coarse_layer_on_rejected_step;
  // Coarse cells are large: every stride-th sample describes them as well.
  control.point_stride =
      std::min(options.max_coarse_point_stride, 1 << std::min(20, n - layer));
  return control;
}

StageControl StageControlOn(const LayerScheduleOptions& options,
                            const LayeredGrid& map,
                            int layer) {
  const int n = map.num_layers();
  StageControl control = StageControlFor(options, layer, n);
  if (layer < n) {
    control.rejected_step_tolerance =
        options.coarse_rejected_step_cells * map.layer(layer).cell_size();
  }
  return control;
}

const OptionTable& LayerScheduleOptionsTable() {
  using S = LayerScheduleOptions;
  static const OptionTable table =
      OptionTableBuilder<S>("LayerScheduleOptions")
          .Int("start_layer",
               &S::start_layer,
               Closed(-16, 16),
               "1-based start layer s; <= 0 counts from the finest (0 = last "
               "layer).")
          .Int("iterations_per_layer",
               &S::iterations_per_layer,
               Closed(1, 1000),
               "Iterations on every layer but the last.")
          .Int("max_final_iterations",
               &S::max_final_iterations,
               Closed(1, 10000),
               "Cap on the last layer's iterations.")
          .Double("step_tolerance",
                  &S::step_tolerance,
                  "m and rad",
                  Closed(1e-12, 1.0),
                  "The last layer converges when a successful step has "
                  "||delta xi|| below this.")
          .Double("coarse_step_tolerance",
                  &S::coarse_step_tolerance,
                  "m and rad",
                  Closed(0.0, 1.0),
                  "A coarse layer ends early below this update norm; 0 runs "
                  "every coarse layer fully.")
          .Bool("end_coarse_layer_on_rejected_step",
                &S::end_coarse_layer_on_rejected_step,
                "A coarse layer ends at its first rejected step (its minimum "
                "at its resolution).")
          .Double("coarse_rejected_step_cells",
                  &S::coarse_rejected_step_cells,
                  "cells",
                  Closed(0.0, 1.0),
                  "A coarse layer also ends at a rejected step shorter than "
                  "this many of its cell edges; 0: off.")
          .Int("max_coarse_point_stride",
               &S::max_coarse_point_stride,
               Closed(1, 1024),
               "Layer i of n uses every min(2^(n-i), this)-th sample (1 = "
               "all).")
          .Double("cells_per_uncertainty",
                  &S::cells_per_uncertainty,
                  "",
                  Closed(0.5, 100.0),
                  "With a known guess uncertainty d, start on the finest "
                  "layer whose cell is >= this * d.")
          .Validator(&S::IsValid)
          .Build();
  return table;
}

bool LayerScheduleOptions::IsValid(std::string* error) const {
  return LayerScheduleOptionsTable().Check(*this, error);
}

LayerScheduleOptions PaperLayerScheduleOptions() {
  LayerScheduleOptions options;
  options.start_layer = 2;
  options.iterations_per_layer = 3;
  options.max_coarse_point_stride = 1;
  options.coarse_rejected_step_cells = 0.0;
  options.step_tolerance = 1e-4;
  return options;
}

int ResolveStartLayer(const LayerScheduleOptions& options, int num_layers) {
  const int s = options.start_layer > 0 ? options.start_layer
                                        : num_layers + options.start_layer;
  return std::clamp(s, 1, num_layers);
}

int StartLayerForUncertainty(const LayerScheduleOptions& options,
                             const LayeredGrid& map,
                             double displacement_m) {
  const double needed = options.cells_per_uncertainty * displacement_m;
  for (int layer = map.num_layers(); layer > 1; --layer) {
    if (map.layer(layer).cell_size() >= needed) return layer;
  }
  return 1;
}

void RunLayerSchedule(const LayerScheduleOptions& options,
                      int start_layer,
                      const LayeredGrid& reference_map,
                      double start_time_s,
                      Backend* backend,
                      Vector6d* reference_from_input_xi,
                      ScheduleSummary* summary) {
  CHECK(backend != nullptr);
  CHECK(summary != nullptr);
  *summary = ScheduleSummary();
  const int n = reference_map.num_layers();
  summary->iterations_per_layer.assign(static_cast<size_t>(n), 0);
  CHECK(start_layer >= 1 && start_layer <= n) << "start layer " << start_layer;
  for (int layer = start_layer; layer <= n; ++layer) {
    const double stage_start_s = NowSeconds() - start_time_s;
    StageSummary stage;
    backend->SolveStage(reference_map.layer(layer),
                        StageControlOn(options, reference_map, layer),
                        reference_from_input_xi,
                        &stage);
    summary->iterations_per_layer[static_cast<size_t>(layer - 1)] =
        stage.iterations();
    for (IterationRecord record : stage.trace) {
      record.layer = layer;
      record.iteration = static_cast<int>(summary->trace.size()) + 1;
      record.time_s += stage_start_s;
      summary->trace.push_back(record);
    }
    if (stage.termination_type == TerminationType::FAILURE) {
      summary->termination_type = TerminationType::FAILURE;
      summary->message =
          "layer " + std::to_string(layer) + ": " + stage.message;
      return;
    }
    if (layer == n) {
      summary->termination_type = stage.termination_type;
      summary->message = stage.termination_type == TerminationType::CONVERGENCE
                             ? "converged on layer " + std::to_string(layer)
                             : "iteration cap reached on layer " +
                                   std::to_string(layer) + " (" +
                                   stage.message + ")";
    }
  }
}

}  // namespace mlndt
