// RunLayerSchedule drives a fake Backend that records every stage it is asked
// to solve and returns a scripted trace, so the tests see exactly which
// layers, controls and poses the schedule hands out and what it makes of the
// stages' traces and terminations (Table 1 of the paper).

#include "mlndt/schedule/layer_scheduler.h"

#include <glog/logging.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "mlndt/common/timer.h"
#include "tests/testing/synthetic_scene.h"

namespace mlndt {
namespace {

// The paper's four layers over a street scene.
const LayeredGrid& Map() {
  static const LayeredGrid* map = [] {
    auto* grid = new LayeredGrid;
    std::string error;
    CHECK(LayeredGrid::Build(PaperLayeredGridOptions(),
                             testing::StreetScene(8000, 0.02, 3),
                             grid,
                             &error))
        << error;
    CHECK_EQ(grid->num_layers(), 4);
    return grid;
  }();
  return *map;
}

// What one stage returns.
struct StageScript {
  int records = 1;
  TerminationType termination = TerminationType::NO_CONVERGENCE;
  std::string message = "iteration cap reached";
};

// What one stage was asked.
struct StageCall {
  const NdtLayer* layer = nullptr;
  double cell_size = 0.0;
  StageControl control;
  Vector6d xi_in = Vector6d::Zero();
  double entered_s = 0.0, left_s = 0.0;  // NowSeconds().
  std::vector<double> record_times_s;    // The stage-local times returned.
};

// Each stage adds 1 to xi(0) per record and returns records whose score
// 100 * stage + k (stage 1-based, k 0-based) identifies them, with honest
// stage-local times.
class FakeBackend : public Backend {
 public:
  explicit FakeBackend(std::vector<StageScript> script)
      : script_(std::move(script)) {}

  void SetProblem(const std::vector<Eigen::Vector3d>&,
                  const ObjectiveOptions&,
                  int) override {}

  void SolveStage(const NdtLayer& layer,
                  const StageControl& control,
                  Vector6d* xi,
                  StageSummary* summary) override {
    StageCall call;
    call.entered_s = NowSeconds();
    call.layer = &layer;
    call.cell_size = layer.cell_size();
    call.control = control;
    call.xi_in = *xi;
    CHECK_LT(calls_.size(), script_.size()) << "more stages than scripted";
    const StageScript& script = script_[calls_.size()];
    *summary = StageSummary();
    for (int k = 0; k < script.records; ++k) {
      (*xi)(0) += 1.0;
      IterationRecord record;
      record.layer = -1;  // The scheduler's to set.
      record.iteration = -1;
      record.score = 100.0 * static_cast<double>(calls_.size() + 1) + k;
      record.step_norm = 0.5 * k;
      record.step_is_successful = k % 2 == 0;
      record.reference_from_input_xi = *xi;
      record.time_s = NowSeconds() - call.entered_s;
      call.record_times_s.push_back(record.time_s);
      summary->trace.push_back(record);
    }
    summary->termination_type = script.termination;
    summary->message = script.message;
    summary->final_score =
        summary->trace.empty() ? 0.0 : summary->trace.back().score;
    call.left_s = NowSeconds();
    calls_.push_back(call);
  }

  const std::vector<StageCall>& calls() const { return calls_; }

 private:
  const std::vector<StageScript> script_;
  std::vector<StageCall> calls_;
};

// One stage per entry, with that many records, ending NO_CONVERGENCE.
std::vector<StageScript> Script(const std::vector<int>& records) {
  std::vector<StageScript> script(records.size());
  for (size_t i = 0; i < records.size(); ++i) script[i].records = records[i];
  return script;
}

ScheduleSummary RunSchedule(const LayerScheduleOptions& options,
                            FakeBackend* backend,
                            Vector6d* xi,
                            double start_time_s = NowSeconds()) {
  ScheduleSummary summary;
  RunLayerSchedule(options,
                   ResolveStartLayer(options, Map().num_layers()),
                   Map(),
                   start_time_s,
                   backend,
                   xi,
                   &summary);
  return summary;
}

// Catches: a schedule that skips or repeats a layer, runs them coarse-last,
// or starts elsewhere than ResolveStartLayer.
TEST(RunLayerSchedule, StagesRunFromTheStartLayerToTheLast) {
  // (start_layer, first layer run) on 4 layers.
  const std::pair<int, int> starts[] = {
      {1, 1}, {2, 2}, {4, 4}, {0, 4}, {-1, 3}};
  for (const auto& [start, first] : starts) {
    SCOPED_TRACE(start);
    LayerScheduleOptions options;
    options.start_layer = start;
    FakeBackend backend(Script(std::vector<int>(5 - first, 1)));
    Vector6d xi = Vector6d::Zero();
    RunSchedule(options, &backend, &xi);
    ASSERT_EQ(backend.calls().size(), static_cast<size_t>(5 - first));
    for (int layer = first; layer <= 4; ++layer) {
      const StageCall& call = backend.calls()[layer - first];
      EXPECT_EQ(call.layer, &Map().layer(layer)) << "layer " << layer;
      EXPECT_EQ(call.cell_size, Map().layer(layer).cell_size());
    }
  }
  // The cells shrink from layer to layer, so the order above is coarse to
  // fine.
  for (int layer = 2; layer <= 4; ++layer) {
    EXPECT_LT(Map().layer(layer).cell_size(),
              Map().layer(layer - 1).cell_size());
  }
}

// Catches: coarse and final controls swapped, the coarse tolerance applied to
// the last layer (or the reverse), a stride of 2^(n - i + 1) or 2^(n - i - 1)
// (off by one), the cap not applied.
TEST(RunLayerSchedule, StageControlsFollowTheOptions) {
  LayerScheduleOptions options;
  options.start_layer = 1;
  options.iterations_per_layer = 5;
  options.max_final_iterations = 17;
  options.step_tolerance = 1e-5;
  options.coarse_step_tolerance = 1e-3;
  options.end_coarse_layer_on_rejected_step = true;
  const struct {
    int max_stride;
    std::vector<int> strides;  // Layers 1..4.
  } cases[] = {{1024, {8, 4, 2, 1}}, {4, {4, 4, 2, 1}}, {1, {1, 1, 1, 1}}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.max_stride);
    options.max_coarse_point_stride = c.max_stride;
    FakeBackend backend(Script({1, 1, 1, 1}));
    Vector6d xi = Vector6d::Zero();
    RunSchedule(options, &backend, &xi);
    ASSERT_EQ(backend.calls().size(), 4u);
    for (int layer = 1; layer <= 4; ++layer) {
      SCOPED_TRACE(layer);
      const StageControl& control = backend.calls()[layer - 1].control;
      const bool last = layer == 4;
      EXPECT_EQ(control.max_iterations, last ? 17 : 5);
      EXPECT_EQ(control.step_tolerance, last ? 1e-5 : 1e-3);
      EXPECT_EQ(control.point_stride, c.strides[layer - 1]);
      EXPECT_EQ(control.end_on_rejected_step, !last);
    }
  }
  options.end_coarse_layer_on_rejected_step = false;
  FakeBackend backend(Script({1, 1, 1, 1}));
  Vector6d xi = Vector6d::Zero();
  RunSchedule(options, &backend, &xi);
  for (const StageCall& call : backend.calls()) {
    EXPECT_FALSE(call.control.end_on_rejected_step);
  }
  EXPECT_FALSE(PaperLayerScheduleOptions().end_coarse_layer_on_rejected_step);
}

// Catches: the rejected-step tolerance not scaled by the layer's own cell
// edge, or applied to the last layer (which must end on a taken step).
TEST(RunLayerSchedule, RejectedStepToleranceFollowsEachCoarseCell) {
  LayerScheduleOptions options;
  options.start_layer = 1;
  options.coarse_rejected_step_cells = 0.01;
  FakeBackend backend(Script({1, 1, 1, 1}));
  Vector6d xi = Vector6d::Zero();
  RunSchedule(options, &backend, &xi);
  ASSERT_EQ(backend.calls().size(), 4u);
  for (int layer = 1; layer <= 4; ++layer) {
    SCOPED_TRACE(layer);
    const StageControl& control = backend.calls()[layer - 1].control;
    EXPECT_DOUBLE_EQ(control.rejected_step_tolerance,
                     layer == 4 ? 0.0 : 0.01 * Map().layer(layer).cell_size());
  }
  options.coarse_rejected_step_cells = 0.0;
  FakeBackend off(Script({1, 1, 1, 1}));
  RunSchedule(options, &off, &xi);
  for (const StageCall& call : off.calls()) {
    EXPECT_EQ(call.control.rejected_step_tolerance, 0.0);
  }
}

// Catches: iterations numbered per stage or from 0, records not stamped with
// their layer (or with the stage index), times not offset by the stage's
// start or offset by the absolute clock, records reordered or dropped,
// iterations_per_layer indexed from the start layer instead of layer 1.
TEST(RunLayerSchedule, TraceIsRenumberedStampedAndTimed) {
  LayerScheduleOptions options;
  options.start_layer = 1;
  const std::vector<int> records = {2, 3, 1, 4};
  FakeBackend backend(Script(records));
  Vector6d xi = Vector6d::Zero();
  // The registration started 1000 s ago: every time is at least that.
  const double start_time_s = NowSeconds() - 1000.0;
  const double before_s = NowSeconds();
  const ScheduleSummary summary =
      RunSchedule(options, &backend, &xi, start_time_s);
  ASSERT_EQ(summary.trace.size(), 10u);
  EXPECT_EQ(summary.iterations_per_layer, records);

  size_t i = 0;
  double previous_time_s = 0.0;
  for (int layer = 1; layer <= 4; ++layer) {
    const StageCall& call = backend.calls()[layer - 1];
    // The scheduler took the stage's start between the previous stage's
    // return and this stage's call.
    const double earliest_s =
        (layer == 1 ? before_s : backend.calls()[layer - 2].left_s) -
        start_time_s;
    const double latest_s = call.entered_s - start_time_s;
    for (int k = 0; k < records[layer - 1]; ++k, ++i) {
      SCOPED_TRACE(::testing::Message() << "layer " << layer << ", k " << k);
      const IterationRecord& record = summary.trace[i];
      EXPECT_EQ(record.iteration, static_cast<int>(i) + 1);
      EXPECT_EQ(record.layer, layer);
      EXPECT_EQ(record.score, 100.0 * layer + k);
      EXPECT_EQ(record.step_norm, 0.5 * k);
      EXPECT_EQ(record.step_is_successful, k % 2 == 0);
      EXPECT_EQ(record.reference_from_input_xi(0), static_cast<double>(i + 1));
      const double stage_start_s = record.time_s - call.record_times_s[k];
      EXPECT_GE(stage_start_s, earliest_s - 1e-9);
      EXPECT_LE(stage_start_s, latest_s + 1e-9);
      EXPECT_GE(record.time_s, 1000.0);
      EXPECT_GE(record.time_s, previous_time_s);  // Monotone.
      previous_time_s = record.time_s;
    }
  }
}

// Catches: records stamped with the stage index (1 for the first stage)
// rather than the layer, which only shows when the schedule starts below 1.
TEST(RunLayerSchedule, RecordsAreStampedWithTheLayerNotTheStage) {
  LayerScheduleOptions options;
  options.start_layer = 3;
  FakeBackend backend(Script({2, 1}));
  Vector6d xi = Vector6d::Zero();
  const ScheduleSummary summary = RunSchedule(options, &backend, &xi);
  ASSERT_EQ(summary.trace.size(), 3u);
  EXPECT_EQ(summary.trace[0].layer, 3);
  EXPECT_EQ(summary.trace[1].layer, 3);
  EXPECT_EQ(summary.trace[2].layer, 4);
  EXPECT_EQ(summary.trace[0].iteration, 1);
  EXPECT_EQ(summary.trace[2].iteration, 3);
}

// Catches: a stage starting from the initial pose instead of the previous
// stage's result.
TEST(RunLayerSchedule, PoseCarriesFromStageToStage) {
  LayerScheduleOptions options;
  options.start_layer = 2;
  FakeBackend backend(Script({2, 3, 4}));
  Vector6d xi = Vector6d::Zero();
  xi(1) = 0.25;
  const ScheduleSummary summary = RunSchedule(options, &backend, &xi);
  ASSERT_EQ(backend.calls().size(), 3u);
  EXPECT_EQ(backend.calls()[0].xi_in(0), 0.0);
  EXPECT_EQ(backend.calls()[1].xi_in(0), 2.0);
  EXPECT_EQ(backend.calls()[2].xi_in(0), 5.0);
  EXPECT_EQ(xi(0), 9.0);
  EXPECT_EQ(xi(1), 0.25);
  EXPECT_EQ(summary.iterations_per_layer, std::vector<int>({0, 2, 3, 4}));
}

// Catches: a failed stage that does not stop the schedule, a message without
// the layer, the failed stage's records dropped from the trace.
TEST(RunLayerSchedule, FailureStopsTheScheduleAndNamesTheLayer) {
  for (const int failing : {2, 4}) {
    SCOPED_TRACE(failing);
    std::vector<StageScript> script = Script({1, 2, 3, 4});
    script[failing - 1].termination = TerminationType::FAILURE;
    script[failing - 1].message = "the step is not finite";
    LayerScheduleOptions options;
    options.start_layer = 1;
    FakeBackend backend(script);
    Vector6d xi = Vector6d::Zero();
    const ScheduleSummary summary = RunSchedule(options, &backend, &xi);
    EXPECT_EQ(backend.calls().size(), static_cast<size_t>(failing));
    EXPECT_EQ(summary.termination_type, TerminationType::FAILURE);
    EXPECT_EQ(summary.message,
              "layer " + std::to_string(failing) + ": the step is not finite");
    // Records 1 + 2 + ... up to the failed stage.
    EXPECT_EQ(summary.trace.size(),
              static_cast<size_t>(failing * (failing + 1) / 2));
    EXPECT_EQ(summary.trace.back().layer, failing);
  }
}

// Catches: a coarse stage's CONVERGENCE ending the schedule, a coarse
// NO_CONVERGENCE (the normal end of a coarse stage) reported, the last
// stage's message dropped.
TEST(RunLayerSchedule, LastStageDecidesTheTermination) {
  LayerScheduleOptions options;
  options.start_layer = 1;
  {
    std::vector<StageScript> script = Script({1, 1, 1, 3});
    script[1].termination = TerminationType::CONVERGENCE;  // Coarse.
    script[1].message = "update norm below tolerance";
    script[3].termination = TerminationType::NO_CONVERGENCE;
    script[3].message = "iteration cap reached";
    FakeBackend backend(script);
    Vector6d xi = Vector6d::Zero();
    const ScheduleSummary summary = RunSchedule(options, &backend, &xi);
    EXPECT_EQ(backend.calls().size(), 4u);
    EXPECT_EQ(summary.termination_type, TerminationType::NO_CONVERGENCE);
    EXPECT_EQ(summary.message,
              "iteration cap reached on layer 4 (iteration cap reached)");
  }
  {
    std::vector<StageScript> script = Script({1, 1, 1, 3});
    script[3].termination = TerminationType::CONVERGENCE;
    script[3].message = "update norm below tolerance";
    FakeBackend backend(script);
    Vector6d xi = Vector6d::Zero();
    const ScheduleSummary summary = RunSchedule(options, &backend, &xi);
    EXPECT_EQ(backend.calls().size(), 4u);
    EXPECT_EQ(summary.termination_type, TerminationType::CONVERGENCE);
    EXPECT_EQ(summary.message, "converged on layer 4");
  }
}

TEST(ResolveStartLayer, PositiveZeroAndNegativeWithClamping) {
  const struct {
    int start_layer, num_layers, expected;
  } cases[] = {
      {1, 4, 1},
      {2, 4, 2},
      {4, 4, 4},
      {5, 4, 4},
      {16, 4, 4},
      {0, 4, 4},
      {-1, 4, 3},
      {-3, 4, 1},
      {-4, 4, 1},
      {-16, 4, 1},
      {0, 1, 1},
      {-1, 1, 1},
      {3, 1, 1},
      {0, 9, 9},
      {-2, 9, 7},
      {2, 12, 2},
      {-11, 12, 1},
      {-10, 12, 2},
  };
  for (const auto& c : cases) {
    LayerScheduleOptions options;
    options.start_layer = c.start_layer;
    EXPECT_EQ(ResolveStartLayer(options, c.num_layers), c.expected)
        << "start_layer " << c.start_layer << " of " << c.num_layers;
  }
}

// Checks IsValid with one field set to each value: accepted for `valid`,
// refused with an error naming `name` for `invalid`.
template <typename T>
void ExpectRange(T LayerScheduleOptions::*field,
                 const char* name,
                 const std::vector<T>& valid,
                 const std::vector<T>& invalid) {
  for (const T value : valid) {
    LayerScheduleOptions options;
    options.*field = value;
    std::string error;
    EXPECT_TRUE(options.IsValid(&error)) << name << " = " << value << error;
  }
  for (const T value : invalid) {
    LayerScheduleOptions options;
    options.*field = value;
    std::string error;
    EXPECT_FALSE(options.IsValid(&error)) << name << " = " << value;
    EXPECT_NE(error.find(name), std::string::npos) << error;
  }
}

TEST(LayerScheduleOptions, IsValidRanges) {
  using O = LayerScheduleOptions;
  const double nan = std::nan("");
  std::string error;
  EXPECT_TRUE(O().IsValid(&error)) << error;
  ExpectRange(&O::start_layer, "start_layer", {-16, 0, 16}, {-17, 17});
  ExpectRange(
      &O::iterations_per_layer, "iterations_per_layer", {1, 1000}, {0, 1001});
  ExpectRange(
      &O::max_final_iterations, "max_final_iterations", {1, 10000}, {0, 10001});
  ExpectRange(&O::step_tolerance,
              "step_tolerance",
              {1e-12, 1.0},
              {0.0, 1e-13, 1.5, nan});
  ExpectRange(&O::coarse_step_tolerance,
              "coarse_step_tolerance",
              {0.0, 1.0},
              {-1e-9, 1.5, nan});
  ExpectRange(&O::max_coarse_point_stride,
              "max_coarse_point_stride",
              {1, 1024},
              {0, 1025});
}

// Catches: a preset drifting from Table 1 (start 2, 3 iterations, every
// point), or changing what it does not mention.
TEST(PaperLayerScheduleOptions, IsTable1) {
  const LayerScheduleOptions paper = PaperLayerScheduleOptions();
  const LayerScheduleOptions defaults;
  std::string error;
  EXPECT_TRUE(paper.IsValid(&error)) << error;
  EXPECT_EQ(paper.start_layer, 2);
  EXPECT_EQ(paper.iterations_per_layer, 3);
  EXPECT_EQ(paper.max_coarse_point_stride, 1);
  EXPECT_EQ(paper.coarse_step_tolerance, 0.0);  // Exactly 3 iterations.
  EXPECT_EQ(paper.max_final_iterations, defaults.max_final_iterations);
  EXPECT_EQ(paper.step_tolerance, 1e-4);  // The earlier default, kept.

  FakeBackend backend(Script({3, 3, 5}));
  Vector6d xi = Vector6d::Zero();
  const ScheduleSummary summary = RunSchedule(paper, &backend, &xi);
  ASSERT_EQ(backend.calls().size(), 3u);
  EXPECT_EQ(backend.calls()[0].layer, &Map().layer(2));
  for (const StageCall& call : backend.calls()) {
    EXPECT_EQ(call.control.point_stride, 1);
  }
  EXPECT_EQ(backend.calls()[0].control.max_iterations, 3);
  EXPECT_EQ(backend.calls()[1].control.max_iterations, 3);
  EXPECT_EQ(summary.iterations_per_layer, std::vector<int>({0, 3, 3, 5}));
}

}  // namespace
}  // namespace mlndt
