// The Ceres backend keeps one cost function per input point across stages
// (ceres_backend.h). These tests check that the reuse is invisible: a stage
// with a point stride gives what a fresh backend gives on the thinned points,
// and a backend handed other points or another policy gives what a fresh one
// gives. A backend that ignored the stride, mis-indexed its pool or kept a
// stale pool would converge to a nearby but different pose, which the exact
// comparisons catch.

#include "mlndt/solvers/ceres_backend.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "mlndt/cloud/io.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/registration/registration.h"
#include "mlndt/sampling/point_sampler.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

struct Koide3 {
  LayeredGrid map;
  std::vector<Eigen::Vector3d> samples;
};

const Koide3& Koide3Pair() {
  static const Koide3* pair = [] {
    auto* p = new Koide3;
    PointCloud reference, input, sampled;
    std::string error;
    CHECK(ReadPointCloud(testing::BundledDataPath("koide3/251370668.pcd"),
                         &reference,
                         nullptr,
                         &error))
        << error;
    CHECK(ReadPointCloud(testing::BundledDataPath("koide3/251371071.pcd"),
                         &input,
                         nullptr,
                         &error))
        << error;
    CHECK(LayeredGrid::Build(
        DefaultRegistrationGridOptions(), reference, &p->map, &error))
        << error;
    CHECK(SamplePoints(SamplingOptions(), input, &sampled, nullptr, &error))
        << error;
    p->samples = sampled.points();
    return p;
  }();
  return *pair;
}

StageOptions Stage(int layer, int stride, UnmatchedPolicy policy) {
  StageOptions stage;
  stage.layer = layer;
  stage.max_iterations = 6;
  stage.point_stride = stride;
  stage.unmatched_policy = policy;
  stage.loss = LossType::CAUCHY;
  stage.loss_scale = 3.0;
  return stage;
}

// Runs one stage from the identity with `backend`; returns the pose.
Vector6d Solve(CeresBackend* backend,
               int layer,
               const std::vector<Eigen::Vector3d>& points,
               const StageOptions& stage) {
  Vector6d xi = Vector6d::Zero();
  StageSummary summary;
  backend->SolveStage(
      Koide3Pair().map.layer(layer), points, stage, &xi, &summary);
  EXPECT_NE(summary.termination_type, TerminationType::FAILURE)
      << summary.message;
  EXPECT_GT(summary.iterations, 0);
  return xi;
}

std::vector<Eigen::Vector3d> EveryNth(
    const std::vector<Eigen::Vector3d>& points, size_t n) {
  std::vector<Eigen::Vector3d> thinned;
  for (size_t i = 0; i < points.size(); i += n) thinned.push_back(points[i]);
  return thinned;
}

TEST(CeresBackend, PointStrideMatchesPreThinnedPoints) {
  const Koide3& pair = Koide3Pair();
  const UnmatchedPolicy policy = UnmatchedPolicy::NEAREST_CELL;
  for (const int stride : {2, 4}) {
    SCOPED_TRACE(stride);
    CeresBackend strided{CeresBackendOptions()};
    CeresBackend fresh{CeresBackendOptions()};
    const Vector6d a =
        Solve(&strided, 3, pair.samples, Stage(3, stride, policy));
    const Vector6d b =
        Solve(&fresh,
              3,
              EveryNth(pair.samples, static_cast<size_t>(stride)),
              Stage(3, 1, policy));
    EXPECT_GT(a.head<3>().norm(), 0.05);  // The stage moved the pose.
    EXPECT_EQ(a, b);
  }
}

TEST(CeresBackend, ReusedAcrossLayersLikeFreshBackends) {
  const Koide3& pair = Koide3Pair();
  const UnmatchedPolicy policy = UnmatchedPolicy::NEAREST_CELL;
  CeresBackend reused{CeresBackendOptions()};
  for (const int layer : {2, 4, 5}) {
    SCOPED_TRACE(layer);
    CeresBackend fresh{CeresBackendOptions()};
    EXPECT_EQ(Solve(&reused, layer, pair.samples, Stage(layer, 1, policy)),
              Solve(&fresh, layer, pair.samples, Stage(layer, 1, policy)));
  }
}

TEST(CeresBackend, OtherPointsOrPolicyGiveWhatAFreshBackendGives) {
  const Koide3& pair = Koide3Pair();
  const std::vector<Eigen::Vector3d> first_half(
      pair.samples.begin(), pair.samples.begin() + pair.samples.size() / 2);
  const std::vector<Eigen::Vector3d> second_half(
      pair.samples.begin() + pair.samples.size() / 2, pair.samples.end());
  CeresBackend reused{CeresBackendOptions()};
  Solve(&reused, 4, first_half, Stage(4, 1, UnmatchedPolicy::NEAREST_CELL));
  {
    CeresBackend fresh{CeresBackendOptions()};
    EXPECT_EQ(Solve(&reused,
                    4,
                    second_half,
                    Stage(4, 1, UnmatchedPolicy::NEAREST_CELL)),
              Solve(&fresh,
                    4,
                    second_half,
                    Stage(4, 1, UnmatchedPolicy::NEAREST_CELL)));
  }
  {
    CeresBackend fresh{CeresBackendOptions()};
    const Vector6d zero = Solve(
        &fresh, 4, second_half, Stage(4, 1, UnmatchedPolicy::ZERO_RESIDUAL));
    EXPECT_EQ(Solve(&reused,
                    4,
                    second_half,
                    Stage(4, 1, UnmatchedPolicy::ZERO_RESIDUAL)),
              zero);
    // The policy matters on this layer, so a stale pool would show.
    CeresBackend nearest{CeresBackendOptions()};
    EXPECT_NE(Solve(&nearest,
                    4,
                    second_half,
                    Stage(4, 1, UnmatchedPolicy::NEAREST_CELL)),
              zero);
  }
}

TEST(CeresBackendDeathTest, ZeroStrideIsAProgrammingError) {
  CeresBackend backend{CeresBackendOptions()};
  Vector6d xi = Vector6d::Zero();
  StageSummary summary;
  EXPECT_DEATH(backend.SolveStage(Koide3Pair().map.layer(1),
                                  Koide3Pair().samples,
                                  Stage(1, 0, UnmatchedPolicy::NEAREST_CELL),
                                  &xi,
                                  &summary),
               "point_stride");
}

}  // namespace
}  // namespace mlndt
