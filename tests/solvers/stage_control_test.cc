// When a stage ends (StageControl, backend.h): on a short step, taken or
// rejected, and at the first rejected step of a coarse layer. The rules are
// checked alone, then on every backend with the bundled koide3 pair.

#include <glog/logging.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "mlndt/solvers/backend_factory.h"
#include "tests/testing/koide3_pair.h"

namespace mlndt {
namespace {

// Catches: a short rejected step counted as converged (a last layer that
// keeps rejecting must end at its cap), a rejected step ending a stage that
// did not ask for it.
TEST(StageControl, EndAfterFollowsItsFields) {
  StageControl control;
  control.step_tolerance = 1e-3;
  EXPECT_EQ(control.EndAfter(5e-4, true), StageEnd::CONVERGED);
  EXPECT_EQ(control.EndAfter(5e-4, false), StageEnd::NONE);
  EXPECT_EQ(control.EndAfter(5e-3, false), StageEnd::NONE);
  control.end_on_rejected_step = true;
  EXPECT_EQ(control.EndAfter(5e-3, false), StageEnd::LAYER_MINIMUM);
  EXPECT_EQ(control.EndAfter(5e-3, true), StageEnd::NONE);
  control.step_tolerance = 0.0;  // Coarse: no tolerance.
  EXPECT_EQ(control.EndAfter(1e-9, true), StageEnd::NONE);
  control.end_on_rejected_step = false;
  control.rejected_step_tolerance = 1e-2;
  EXPECT_EQ(control.EndAfter(5e-3, false), StageEnd::LAYER_MINIMUM);
  EXPECT_EQ(control.EndAfter(2e-2, false), StageEnd::NONE);
  EXPECT_EQ(control.EndAfter(5e-3, true), StageEnd::NONE);

  StageSummary summary;
  EndStage(StageEnd::LAYER_MINIMUM, &summary);
  EXPECT_EQ(summary.termination_type, TerminationType::CONVERGENCE);
  summary = StageSummary();
  EndStage(StageEnd::NONE, &summary);
  EXPECT_EQ(summary.termination_type, TerminationType::FAILURE);
}

using testing::Koide3Pair;

std::vector<BackendType> AllBackends() {
  return {BackendType::CERES,
          BackendType::LEVENBERG_MARQUARDT,
          BackendType::NEWTON};
}

std::unique_ptr<Backend> MakeBackend(BackendType type) {
  BackendOptions options;
  options.type = type;
  std::string error;
  std::unique_ptr<Backend> backend = CreateBackend(options, &error);
  CHECK(backend != nullptr) << error;
  backend->SetProblem(Koide3Pair().samples, ObjectiveOptions(), 1);
  return backend;
}

// Catches: a backend that ignores end_on_rejected_step (the stage would run
// on after the rejection) or ends without one.
TEST(StageControl, EveryBackendEndsACoarseLayerAtItsFirstRejectedStep) {
  for (const BackendType type : AllBackends()) {
    SCOPED_TRACE(BackendTypeToString(type));
    std::unique_ptr<Backend> backend = MakeBackend(type);
    StageControl control;
    control.max_iterations = 30;
    control.end_on_rejected_step = true;
    Vector6d xi = Vector6d::Zero();
    StageSummary summary;
    backend->SolveStage(Koide3Pair().map.layer(2), control, &xi, &summary);
    ASSERT_GT(summary.iterations(), 1);
    ASSERT_LT(summary.iterations(), 30);
    for (int i = 0; i + 1 < summary.iterations(); ++i) {
      EXPECT_TRUE(summary.trace[static_cast<size_t>(i)].step_is_successful);
    }
    EXPECT_FALSE(summary.trace.back().step_is_successful);
    EXPECT_EQ(summary.termination_type, TerminationType::CONVERGENCE);
  }
}

// Catches: a trust-region backend that converges on a short rejected step
// or runs on past a short successful one. (Newton also ends where its line
// search finds no decrease.)
TEST(StageControl, TrustRegionBackendsConvergeOnTheFirstShortSuccessfulStep) {
  const int last = Koide3Pair().map.num_layers();
  for (const BackendType type :
       {BackendType::CERES, BackendType::LEVENBERG_MARQUARDT}) {
    SCOPED_TRACE(BackendTypeToString(type));
    std::unique_ptr<Backend> backend = MakeBackend(type);
    StageControl control;
    control.max_iterations = 50;
    control.step_tolerance = 1e-3;
    Vector6d xi = Vector6d::Zero();
    StageSummary summary;
    backend->SolveStage(Koide3Pair().map.layer(last), control, &xi, &summary);
    ASSERT_EQ(summary.termination_type, TerminationType::CONVERGENCE)
        << summary.message;
    EXPECT_LT(summary.trace.back().step_norm, 1e-3);
    EXPECT_TRUE(summary.trace.back().step_is_successful);
    for (int i = 0; i + 1 < summary.iterations(); ++i) {
      const IterationRecord& record = summary.trace[static_cast<size_t>(i)];
      EXPECT_FALSE(record.step_is_successful && record.step_norm < 1e-3);
    }
    EXPECT_GT(xi.head<3>().norm(), 0.3);  // The pair is 0.5 m apart.
  }
}

}  // namespace
}  // namespace mlndt
