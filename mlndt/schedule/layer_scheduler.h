#pragma once

// The registration process of ML-NDT (Table 1): start on layer s, run a fixed
// number of iterations on each layer (three in the paper, Section 4), switch
// to the next finer layer, and run the last layer until the update norm
// falls below a tolerance or an iteration cap is reached. Each stage hands the
// backend the stage's layer; the Ceres backend builds a fresh Problem for it.

#include <string>
#include <vector>

#include "mlndt/grid/layered_grid.h"
#include "mlndt/solvers/backend.h"

namespace mlndt {

struct LayerScheduleOptions {
  // s, the 1-based layer to start on. Values <= 0 count from the finest
  // layer: 0 is the last layer n, -1 is n - 1, and so on, which keeps the
  // meaning when n is derived from a finest cell size. Clamped to layer 1.
  int start_layer = 2;
  int iterations_per_layer =
      3;  // Iterations on every layer but the last. >= 1.
  int max_final_iterations = 30;  // Cap on the last layer's iterations. >= 1.
  // The last layer converges when a successful step has ||delta xi|| below
  // this (metres and radians). > 0.
  double step_tolerance = 1e-4;
  // A coarse layer ends early once a successful step has ||delta xi|| below
  // this; 0 runs every coarse layer for exactly iterations_per_layer
  // iterations, as the paper. >= 0.
  double coarse_step_tolerance = 0.0;
  // Layer i of n uses every s-th sampled point, s = min(2^(n - i), this):
  // a cell twice as large needs fewer points to be located. 1 uses every
  // sampled point on every layer, as the paper. >= 1.
  int max_coarse_point_stride = 1;

  bool IsValid(std::string* error) const;
};

// The 1-based start layer `options.start_layer` resolves to on n layers.
int ResolveStartLayer(const LayerScheduleOptions& options, int num_layers);

struct ScheduleSummary {
  TerminationType termination_type = TerminationType::FAILURE;
  std::string message;
  std::vector<IterationRecord> trace;
  std::vector<int> iterations_per_layer;  // Index i - 1 for layer i.
};

// Runs the stages. `stage_options` supplies the per-point settings (policy,
// loss, start time); the scheduler fills in layer, iterations and tolerance.
void RunLayerSchedule(const LayerScheduleOptions& options,
                      const LayeredGrid& reference_map,
                      const std::vector<Eigen::Vector3d>& input_points,
                      const StageOptions& stage_options,
                      Backend* backend,
                      Vector6d* reference_from_input_xi,
                      ScheduleSummary* summary);

}  // namespace mlndt
