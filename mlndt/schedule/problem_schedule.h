#pragma once

// The layer schedule of Table 1 on a ceres::Problem the caller owns: a pose
// graph or bundle adjustment whose ML-NDT residuals (add_residuals.h,
// add_pair_residuals.h) read their layer through LayerBindings. Each stage
// rebinds every binding to its map's stage layer and calls ceres::Solve on
// the same Problem: no residual block is removed or added, and every stage
// scores the same sampled points (coarse to fine, as the paper moves one
// scan's points from layer to layer).
//
//   LayerBinding binding_0(map_0.layer(1)), binding_1(map_1.layer(1));
//   AddMlNdtPairResiduals(binding_0, samples_1, objective, q0, t0, q1, t1, &p);
//   AddMlNdtPairResiduals(binding_1, samples_2, objective, q1, t1, q2, t2, &p);
//   ... priors, odometry, IMU factors ...
//   ProblemScheduleSummary summary;
//   SolveWithLayerSchedule(LayerScheduleOptions(), solver_options,
//                          {{&binding_0, &map_0}, {&binding_1, &map_1}},
//                          &p, &summary, &error);
//
// Stages count back from the finest layer, so that maps with different
// numbers of layers reach their finest layers together: with K stages (the
// most any map has from its start layer, ResolveStartLayer), stage k of
// 0..K-1 binds a map of n layers starting on s to layer
// max(s, n - (K - 1 - k)). Coarse stages run at most iterations_per_layer
// iterations (ending early on coarse_step_tolerance when it is > 0); the
// last stage runs at most max_final_iterations and converges on a successful
// step whose norm (Ceres' step_norm over all the Problem's parameters, in
// the manifolds' tangent spaces) is below step_tolerance. Each binding
// also gets Register's point stride for its layer (max_coarse_point_stride,
// layer_scheduler.h): one-block pairs (mlndt_pair_factor.h) use every
// stride-th point on coarse layers, per-point blocks stay and use every
// point on every layer, as the paper does. cells_per_uncertainty does not
// apply (StartLayerForUncertainty gives a start_layer for it). After the
// call every binding is on its map's finest layer, with stride 1.

#include <ceres/problem.h>
#include <ceres/solver.h>

#include <string>
#include <vector>

#include "mlndt/common/types.h"
#include "mlndt/cost/layer_binding.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/schedule/layer_scheduler.h"

namespace mlndt {

// A binding the caller's residuals read, and the map whose layers the
// schedule binds it to. Both must outlive the call.
struct ScheduledBinding {
  LayerBinding* binding = nullptr;
  const LayeredGrid* map = nullptr;
};

struct ProblemStageSummary {
  // The 1-based layer each binding was on, in the order of the bindings.
  std::vector<int> layers;
  int iterations = 0;  // Ceres iterations (not counting its evaluation 0).
  double initial_cost = 0.0;  // Ceres' cost, 1/2 sum rho(||r||^2).
  double final_cost = 0.0;
  ceres::TerminationType ceres_termination = ceres::FAILURE;
  double time_s = 0.0;  // Wall time of the stage's Solve [s].
};

struct ProblemScheduleSummary {
  // CONVERGENCE when the last stage met step_tolerance (or Ceres' own
  // convergence tests), NO_CONVERGENCE at its iteration cap, FAILURE when a
  // stage failed (message says which).
  TerminationType termination_type = TerminationType::FAILURE;
  std::string message;
  std::vector<ProblemStageSummary> stages;  // Coarse to fine.
  int total_iterations() const;
  double total_time_s() const;
};

// Runs `problem` through the schedule of `schedule` (start_layer,
// iterations_per_layer, max_final_iterations, step_tolerance,
// coarse_step_tolerance), each stage a ceres::Solve with `solver_options`
// (its max_num_iterations is the stage's; its callbacks run in every stage).
// Returns false with *error, before touching a binding, for invalid options,
// no bindings, a null binding or map, or a map without layers.
bool SolveWithLayerSchedule(const LayerScheduleOptions& schedule,
                            const ceres::Solver::Options& solver_options,
                            const std::vector<ScheduledBinding>& bindings,
                            ceres::Problem* problem,
                            ProblemScheduleSummary* summary,
                            std::string* error);

}  // namespace mlndt
