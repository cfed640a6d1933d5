#pragma once

// The registration process of ML-NDT (Table 1): start on layer s, run a fixed
// number of iterations on each layer (three in the paper, Section 4), switch
// to the next finer layer, and run the last layer until the update norm
// falls below a tolerance or an iteration cap is reached. Each stage hands the
// backend the stage's layer; the Ceres backend keeps one Problem per point
// stride and solves it on that layer.
// The scheduler owns the iteration trace: it numbers the backends' records
// over the whole registration and stamps their layer and time.

#include <string>
#include <vector>

#include "mlndt/grid/layered_grid.h"
#include "mlndt/solvers/backend.h"

namespace mlndt {

class OptionTable;

// The library's schedule; PaperLayerScheduleOptions() is the paper's
// (docs/defaults.md compares them).
struct LayerScheduleOptions {
  // s, the 1-based layer to start on. Values <= 0 count from the finest
  // layer: 0 is the last layer n, -1 is n - 1, and so on, which keeps the
  // meaning when n is derived from a finest cell size. Clamped to layer 1.
  // In [-16, 16].
  int start_layer = 1;
  // Iterations on every layer but the last. In [1, 1000].
  int iterations_per_layer = 6;
  // Cap on the last layer's iterations. In [1, 10000].
  int max_final_iterations = 30;
  // The last layer converges when a successful step has ||delta xi|| below
  // this (metres and radians: 1 mm, 0.06 deg). In [1e-12, 1].
  double step_tolerance = 1e-3;
  // A coarse layer ends early once a successful step has ||delta xi||
  // below this; 0
  // runs every coarse layer for exactly iterations_per_layer iterations, as
  // the paper. In [0, 1].
  double coarse_step_tolerance = 0.0;
  // A coarse layer ends at its first rejected step: the objective is
  // piecewise smooth, and a step the layer rejects means its minimum is
  // reached at its resolution (backend.h, StageControl). False (the
  // default, docs/performance.md says why) runs the iterations the
  // tolerances allow, as the paper.
  bool end_coarse_layer_on_rejected_step = false;
  // > 0: a coarse layer also ends at a rejected step shorter than this many
  // of its cell edges (||delta xi||, metres and radians): a step that short
  // is below what the layer resolves, and Ceres' shrinking trust region
  // would only retry nearly the same step (StageControl::
  // rejected_step_tolerance; docs/defaults.md says how the default was
  // chosen). 0 runs the iterations the tolerances allow, as the paper.
  // In [0, 1].
  double coarse_rejected_step_cells = 0.003;
  // Layer i of n uses every s-th sampled point, s = min(2^(n - i), this):
  // a cell twice as large needs fewer points to be located. 1 uses every
  // sampled point on every layer, as the paper. In [1, 1024].
  int max_coarse_point_stride = 8;
  // With a known initial-guess uncertainty (the guess may be off by up to d
  // metres at the input points), the schedule starts on the finest layer
  // whose cell edge is at least this times d, instead of start_layer: the
  // paper's guideline (Section 5.3), finer for better guesses. In [0.5, 100].
  double cells_per_uncertainty = 2.0;

  bool IsValid(std::string* error) const;
};

// LayerScheduleOptions's fields: name, unit, valid range and help
// (option_table.h).
const OptionTable& LayerScheduleOptionsTable();

// Table 1 as the paper runs it: start on layer 2, 3 iterations a layer,
// every sampled point on every layer.
LayerScheduleOptions PaperLayerScheduleOptions();

// The 1-based start layer `options.start_layer` resolves to on n layers.
int ResolveStartLayer(const LayerScheduleOptions& options, int num_layers);

// The finest layer of `map` whose cell edge is at least
// options.cells_per_uncertainty * displacement_m (layer 1 if none is).
int StartLayerForUncertainty(const LayerScheduleOptions& options,
                             const LayeredGrid& map,
                             double displacement_m);

// The control of the stage on `layer` (1-based) of n: iterations, tolerances
// and the point stride (every stride-th sample on coarse layers).
StageControl StageControlFor(const LayerScheduleOptions& options,
                             int layer,
                             int n);

// StageControlFor's control for `layer` of `map`, with the rejected-step
// tolerance of a coarse layer (coarse_rejected_step_cells times its cell
// edge).
StageControl StageControlOn(const LayerScheduleOptions& options,
                            const LayeredGrid& map,
                            int layer);

struct ScheduleSummary {
  TerminationType termination_type = TerminationType::FAILURE;
  std::string message;
  std::vector<IterationRecord> trace;
  std::vector<int> iterations_per_layer;  // Index i - 1 for layer i.
};

// Runs the stages from `start_layer` (1-based) on `backend`, whose
// SetProblem has been called. Trace times count from `start_time_s`
// (NowSeconds() at the registration's start).
void RunLayerSchedule(const LayerScheduleOptions& options,
                      int start_layer,
                      const LayeredGrid& reference_map,
                      double start_time_s,
                      Backend* backend,
                      Vector6d* reference_from_input_xi,
                      ScheduleSummary* summary);

}  // namespace mlndt
