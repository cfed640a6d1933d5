// Anatomy of one Ceres stage on the bundled KITTI pair 0 -> 1 (the finest
// layer, default options, the ~14k GBS samples, at the solution): what one
// auto-diff residual costs, what building and freeing the per-stage
// ceres::Problem costs with fresh functors and with the backend's reused
// ones (LayerBinding), and how a 6-iteration Solve splits into Jacobian
// evaluation, residual evaluation and linear solve (Ceres' own timers).
// docs/performance.md quotes it. CPU time is the figure to compare.

#include <benchmark/benchmark.h>
#include <ceres/ceres.h>
#include <glog/logging.h>

#include <memory>
#include <string>
#include <vector>

#include "mlndt/cost/layer_binding.h"
#include "mlndt/cost/mlndt_point_cost.h"
#include "mlndt/mlndt.h"

namespace mlndt {
namespace {

struct Stage {
  RegistrationOptions options;
  LayeredGrid map;
  std::vector<Eigen::Vector3d> samples;
  Vector6d solution = Vector6d::Zero();
  const NdtLayer& layer() const { return map.layer(map.num_layers()); }
};

const Stage& KittiStage() {
  static const Stage* stage = [] {
    auto* s = new Stage;
    const std::string dir = MLNDT_DATA_DIR;
    PointCloud reference, input, sampled;
    std::string error;
    CHECK(ReadPointCloud(
        dir + "/kitti/pcd/000000.pcd", &reference, nullptr, &error))
        << error;
    CHECK(
        ReadPointCloud(dir + "/kitti/pcd/000001.pcd", &input, nullptr, &error))
        << error;
    CHECK(LayeredGrid::Build(s->options.grid, reference, &s->map, &error))
        << error;
    CHECK(SamplePoints(s->options.sampling, input, &sampled, nullptr, &error))
        << error;
    s->samples = sampled.points();
    RegistrationSummary summary;
    Register(s->options, s->map, input, Isometry3d::Identity(), &summary);
    CHECK(summary.IsSolutionUsable()) << summary.message;
    s->solution = summary.reference_from_input_xi;
    return s;
  }();
  return *stage;
}

std::vector<std::unique_ptr<ceres::CostFunction>> MakeCosts(const Stage& stage,
                                                            LayerSource layer) {
  std::vector<std::unique_ptr<ceres::CostFunction>> costs;
  for (const Eigen::Vector3d& p : stage.samples) {
    costs.emplace_back(MlNdtPointCost::Create(
        layer, p, stage.options.objective.unmatched_policy));
  }
  return costs;
}

// One residual (cell lookup included), value only or with its 3x6 Jacobian.
void BM_AutoDiffResidual(benchmark::State& state) {
  const Stage& stage = KittiStage();
  const auto costs = MakeCosts(stage, stage.layer());
  Vector6d xi = stage.solution;
  const double* parameters[] = {xi.data()};
  double residual[3], jacobian[18];
  double* jacobians[] = {jacobian};
  const bool with_jacobian = state.range(0) == 1;
  for (auto _ : state) {
    xi(0) += 1e-12;  // A new pose per pass, as in an iteration.
    for (const auto& cost : costs) {
      cost->Evaluate(parameters, residual, with_jacobian ? jacobians : nullptr);
      benchmark::DoNotOptimize(residual);
    }
  }
  state.SetItemsProcessed(state.iterations() *
                          static_cast<int64_t>(costs.size()));
  state.SetLabel(with_jacobian ? "with jacobian" : "value only");
}

// Building and freeing a stage's Problem: fresh functors (0) or the pooled,
// rebound ones the Ceres backend uses (1).
void BM_ProblemBuildAndFree(benchmark::State& state) {
  const Stage& stage = KittiStage();
  const bool pooled = state.range(0) == 1;
  LayerBinding binding(stage.layer());
  const auto pool = MakeCosts(stage, binding);
  Vector6d xi = stage.solution;
  for (auto _ : state) {
    ceres::Problem::Options options;
    options.disable_all_safety_checks = true;
    if (pooled) options.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    ceres::Problem problem(options);
    for (size_t i = 0; i < stage.samples.size(); ++i) {
      problem.AddResidualBlock(
          pooled ? pool[i].get()
                 : MlNdtPointCost::Create(
                       stage.layer(),
                       stage.samples[i],
                       stage.options.objective.unmatched_policy),
          nullptr,
          xi.data());
    }
  }
  state.SetItemsProcessed(state.iterations() *
                          static_cast<int64_t>(stage.samples.size()));
  state.SetLabel(pooled ? "pooled functors" : "fresh functors");
}

// A 6-iteration Solve on the finest layer from 0.3 m / 1 deg off the
// solution; counters are Ceres' timers, per Solve.
void BM_StageSolve(benchmark::State& state) {
  const Stage& stage = KittiStage();
  LayerBinding binding(stage.layer());
  const auto pool = MakeCosts(stage, binding);
  ceres::Solver::Summary summary;
  double jacobian_s = 0, residual_s = 0, linear_s = 0, preprocessor_s = 0;
  for (auto _ : state) {
    Vector6d xi = stage.solution;
    xi(0) += 0.3;
    xi(5) += 1.0 * kDegToRad;
    ceres::Problem::Options problem_options;
    problem_options.disable_all_safety_checks = true;
    problem_options.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    ceres::Problem problem(problem_options);
    ceres::LossFunction* loss = CreateLoss(stage.options.objective.loss,
                                           stage.options.objective.loss_scale);
    for (const auto& cost : pool)
      problem.AddResidualBlock(cost.get(), loss, xi.data());
    ceres::Solver::Options options;
    options.linear_solver_type = stage.options.backend.ceres.linear_solver_type;
    options.num_threads = static_cast<int>(state.range(0));
    options.max_num_iterations = 6;
    options.function_tolerance = options.gradient_tolerance =
        options.parameter_tolerance = 0;
    options.logging_type = ceres::SILENT;
    ceres::Solve(options, &problem, &summary);
    jacobian_s += summary.jacobian_evaluation_time_in_seconds;
    residual_s += summary.residual_evaluation_time_in_seconds;
    linear_s += summary.linear_solver_time_in_seconds;
    preprocessor_s += summary.preprocessor_time_in_seconds;
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["jacobian_ms"] = jacobian_s / n * 1e3;
  state.counters["residual_ms"] = residual_s / n * 1e3;
  state.counters["linear_ms"] = linear_s / n * 1e3;
  state.counters["preprocess_ms"] = preprocessor_s / n * 1e3;
  state.counters["evaluations"] = summary.num_jacobian_evaluations;
  state.SetLabel(std::to_string(state.range(0)) + " thread(s)");
}

BENCHMARK(BM_AutoDiffResidual)->Arg(0)->Arg(1);
BENCHMARK(BM_ProblemBuildAndFree)
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StageSolve)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace mlndt

BENCHMARK_MAIN();
