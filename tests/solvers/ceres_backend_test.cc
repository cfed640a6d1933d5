// The Ceres backend keeps one cost function per input point across stages
// (ceres_backend.h). These tests check that the reuse is invisible: a stage
// with a point stride gives what a fresh backend gives on the thinned points,
// and a backend handed other points or another policy (SetProblem again)
// gives what a fresh one gives. A backend that ignored the stride, mis-indexed
// its pool or kept a stale pool would converge to a nearby but different pose,
// which the exact comparisons catch.

#include "mlndt/solvers/ceres_backend.h"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "mlndt/registration/registration.h"
#include "tests/testing/koide3_pair.h"

namespace mlndt {
namespace {

using testing::Koide3Pair;

StageControl Stage(int stride) {
  StageControl control;
  control.max_iterations = 6;
  control.point_stride = stride;
  return control;
}

ObjectiveOptions Objective(UnmatchedPolicy policy) {
  ObjectiveOptions objective;  // Cauchy, scale 3.
  objective.unmatched_policy = policy;
  return objective;
}

// Hands `points` to `backend` and runs one stage from the identity; returns
// the pose.
Vector6d Solve(CeresBackend* backend,
               int layer,
               const std::vector<Eigen::Vector3d>& points,
               UnmatchedPolicy policy,
               const StageControl& control) {
  backend->SetProblem(points, Objective(policy), 1);
  Vector6d xi = Vector6d::Zero();
  StageSummary summary;
  backend->SolveStage(Koide3Pair().map.layer(layer), control, &xi, &summary);
  EXPECT_NE(summary.termination_type, TerminationType::FAILURE)
      << summary.message;
  EXPECT_GT(summary.iterations(), 0);
  return xi;
}

std::vector<Eigen::Vector3d> EveryNth(
    const std::vector<Eigen::Vector3d>& points, size_t n) {
  std::vector<Eigen::Vector3d> thinned;
  for (size_t i = 0; i < points.size(); i += n) thinned.push_back(points[i]);
  return thinned;
}

TEST(CeresBackend, PointStrideMatchesPreThinnedPoints) {
  const testing::Koide3MapAndSamples& pair = Koide3Pair();
  const UnmatchedPolicy policy = UnmatchedPolicy::NEAREST_CELL;
  for (const int stride : {2, 4}) {
    SCOPED_TRACE(stride);
    CeresBackend strided{CeresBackendOptions()};
    CeresBackend fresh{CeresBackendOptions()};
    const Vector6d a = Solve(&strided, 3, pair.samples, policy, Stage(stride));
    const std::vector<Eigen::Vector3d> thinned =
        EveryNth(pair.samples, static_cast<size_t>(stride));
    const Vector6d b = Solve(&fresh, 3, thinned, policy, Stage(1));
    EXPECT_GT(a.head<3>().norm(), 0.05);  // The stage moved the pose.
    EXPECT_EQ(a, b);
  }
}

TEST(CeresBackend, ReusedAcrossLayersLikeFreshBackends) {
  const testing::Koide3MapAndSamples& pair = Koide3Pair();
  const UnmatchedPolicy policy = UnmatchedPolicy::NEAREST_CELL;
  CeresBackend reused{CeresBackendOptions()};
  reused.SetProblem(pair.samples, Objective(policy), 1);
  for (const int layer : {2, 4, 5}) {
    SCOPED_TRACE(layer);
    Vector6d xi = Vector6d::Zero();
    StageSummary summary;
    reused.SolveStage(pair.map.layer(layer), Stage(1), &xi, &summary);
    CeresBackend fresh{CeresBackendOptions()};
    EXPECT_EQ(xi, Solve(&fresh, layer, pair.samples, policy, Stage(1)));
  }
}

// The backend keeps one Problem per point stride (ceres_backend.cc): a later
// stage with a stride seen before solves that Problem again, on another layer
// and from a pose held in another vector. Each stage, in an order that
// returns to every stride, must give the pose, trace and final score that a
// fresh backend gives from the same start.
TEST(CeresBackend, ProblemsKeptPerStrideGiveWhatFreshProblemsGive) {
  const testing::Koide3MapAndSamples& pair = Koide3Pair();
  const UnmatchedPolicy policy = UnmatchedPolicy::NEAREST_CELL;
  CeresBackend reused{CeresBackendOptions()};
  reused.SetProblem(pair.samples, Objective(policy), 1);
  const std::pair<int, int> stages[] = {
      {1, 8}, {2, 8}, {3, 4}, {5, 8}, {4, 2}, {5, 1}, {5, 8}, {4, 1}};
  Vector6d start = Vector6d::Zero();
  for (const auto& [layer, stride] : stages) {
    SCOPED_TRACE("layer " + std::to_string(layer) + " stride " +
                 std::to_string(stride));
    Vector6d xi = start;  // A new vector at every stage.
    StageSummary summary;
    reused.SolveStage(pair.map.layer(layer), Stage(stride), &xi, &summary);
    CeresBackend fresh{CeresBackendOptions()};
    fresh.SetProblem(pair.samples, Objective(policy), 1);
    Vector6d fresh_xi = start;
    StageSummary fresh_summary;
    fresh.SolveStage(
        pair.map.layer(layer), Stage(stride), &fresh_xi, &fresh_summary);
    EXPECT_EQ(xi, fresh_xi);
    EXPECT_EQ(summary.final_score, fresh_summary.final_score);
    ASSERT_EQ(summary.trace.size(), fresh_summary.trace.size());
    for (size_t i = 0; i < summary.trace.size(); ++i) {
      EXPECT_EQ(summary.trace[i].score, fresh_summary.trace[i].score);
      EXPECT_EQ(summary.trace[i].reference_from_input_xi,
                fresh_summary.trace[i].reference_from_input_xi);
    }
    EXPECT_NE(xi, start);  // The stage moved the pose.
    // The next stage starts 0.1 m and 0.2 deg away from where this one
    // ended, so that a Problem holding on to its last pose would show.
    start = xi;
    start(0) += 0.1;
    start(5) += 0.0035;
  }
}

TEST(CeresBackend, SetProblemAgainGivesWhatAFreshBackendGives) {
  const testing::Koide3MapAndSamples& pair = Koide3Pair();
  const std::vector<Eigen::Vector3d> first_half(
      pair.samples.begin(), pair.samples.begin() + pair.samples.size() / 2);
  const std::vector<Eigen::Vector3d> second_half(
      pair.samples.begin() + pair.samples.size() / 2, pair.samples.end());
  const UnmatchedPolicy nearest = UnmatchedPolicy::NEAREST_CELL;
  const UnmatchedPolicy zero = UnmatchedPolicy::ZERO_RESIDUAL;
  CeresBackend reused{CeresBackendOptions()};
  Solve(&reused, 4, first_half, nearest, Stage(1));
  {
    CeresBackend fresh{CeresBackendOptions()};
    EXPECT_EQ(Solve(&reused, 4, second_half, nearest, Stage(1)),
              Solve(&fresh, 4, second_half, nearest, Stage(1)));
  }
  {
    CeresBackend fresh{CeresBackendOptions()};
    const Vector6d with_zero = Solve(&fresh, 4, second_half, zero, Stage(1));
    EXPECT_EQ(Solve(&reused, 4, second_half, zero, Stage(1)), with_zero);
    // The policy matters on this layer, so a stale pool would show.
    CeresBackend other{CeresBackendOptions()};
    EXPECT_NE(Solve(&other, 4, second_half, nearest, Stage(1)), with_zero);
  }
}

TEST(CeresBackendDeathTest, StageBeforeSetProblemIsAProgrammingError) {
  CeresBackend backend{CeresBackendOptions()};
  Vector6d xi = Vector6d::Zero();
  StageSummary summary;
  EXPECT_DEATH(
      backend.SolveStage(Koide3Pair().map.layer(1), Stage(1), &xi, &summary),
      "SetProblem");
}

TEST(CeresBackendDeathTest, ZeroStrideIsAProgrammingError) {
  CeresBackend backend{CeresBackendOptions()};
  backend.SetProblem(
      Koide3Pair().samples, Objective(UnmatchedPolicy::NEAREST_CELL), 1);
  Vector6d xi = Vector6d::Zero();
  StageSummary summary;
  EXPECT_DEATH(
      backend.SolveStage(Koide3Pair().map.layer(1), Stage(0), &xi, &summary),
      "point_stride");
}

}  // namespace
}  // namespace mlndt
