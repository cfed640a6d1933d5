#include "mlndt/registration/registration.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "mlndt/common/pose.h"
#include "tests/testing/synthetic_scene.h"

namespace mlndt {
namespace {

// Registers a second sampling of the street scene, seen from a sensor at
// `reference_from_input`, and returns the summary.
RegistrationSummary RegisterStreet(
    const Isometry3d& reference_from_input,
    const Isometry3d& initial,
    const RegistrationOptions& options = RegistrationOptions()) {
  const PointCloud reference = testing::StreetScene(60000, 0.02, 1);
  const PointCloud input = TransformCloud(reference_from_input.inverse(),
                                          testing::StreetScene(60000, 0.02, 2));
  RegistrationSummary summary;
  Register(options, reference, input, initial, &summary);
  return summary;
}

struct LargeTransformCase {
  double tx, ty, tz, alpha_deg, beta_deg, gamma_deg;
};

class RegistrationLargeTransform
    : public ::testing::TestWithParam<LargeTransformCase> {};

TEST_P(RegistrationLargeTransform, RecoversKnownTransformFromIdentity) {
  const LargeTransformCase& c = GetParam();
  const Isometry3d truth = PoseVectorToIsometry(PoseVectorFromDegrees(
      c.tx, c.ty, c.tz, c.alpha_deg, c.beta_deg, c.gamma_deg));
  const RegistrationSummary summary =
      RegisterStreet(truth, Isometry3d::Identity());
  ASSERT_TRUE(summary.IsSolutionUsable()) << summary.message;
  EXPECT_LT(TranslationErrorM(truth, summary.reference_from_input), 0.05)
      << summary.FullReport();
  EXPECT_LT(RotationErrorRad(truth, summary.reference_from_input) * kRadToDeg,
            0.3)
      << summary.FullReport();
}

INSTANTIATE_TEST_SUITE_P(
    Synthetic,
    RegistrationLargeTransform,
    ::testing::Values(LargeTransformCase{2.0, 0.5, 0.1, 0, 0, 5},
                      LargeTransformCase{5.0, -1.0, 0.0, 1, -1, 15},
                      LargeTransformCase{-3.0, 3.0, 0.2, 0, 2, -25},
                      LargeTransformCase{8.0, 0.0, 0.0, 0, 0, 0}));

TEST(Registration, InverseAlignmentAgrees) {
  // Forward and backward registrations of the same pair are inverses.
  const Isometry3d truth =
      PoseVectorToIsometry(PoseVectorFromDegrees(3, -1, 0.1, 1, 0, 10));
  const PointCloud a = testing::StreetScene(60000, 0.02, 3);
  const PointCloud b =
      TransformCloud(truth.inverse(), testing::StreetScene(60000, 0.02, 4));
  RegistrationSummary forward, backward;
  Register(RegistrationOptions(), a, b, Isometry3d::Identity(), &forward);
  Register(RegistrationOptions(), b, a, Isometry3d::Identity(), &backward);
  ASSERT_TRUE(forward.IsSolutionUsable() && backward.IsSolutionUsable());
  const Isometry3d loop =
      forward.reference_from_input * backward.reference_from_input;
  EXPECT_LT(loop.translation().norm(), 0.05);
  EXPECT_LT(Eigen::AngleAxisd(loop.linear()).angle() * kRadToDeg, 0.3);
}

TEST(Registration, SummaryIsComplete) {
  const Isometry3d truth =
      PoseVectorToIsometry(PoseVectorFromDegrees(1, 0.5, 0, 0, 0, 4));
  const RegistrationSummary s = RegisterStreet(truth, Isometry3d::Identity());
  ASSERT_TRUE(s.IsSolutionUsable()) << s.message;
  EXPECT_EQ(s.termination_type, TerminationType::CONVERGENCE) << s.message;
  ASSERT_FALSE(s.trace.empty());
  int total = 0;
  for (int n : s.iterations_per_layer) total += n;
  EXPECT_EQ(total, s.num_iterations);
  EXPECT_EQ(static_cast<int>(s.trace.size()), s.num_iterations);
  for (size_t i = 1; i < s.trace.size(); ++i) {
    EXPECT_GE(s.trace[i].layer, s.trace[i - 1].layer);  // Coarse to fine.
    EXPECT_GE(s.trace[i].time_s, s.trace[i - 1].time_s);
  }
  EXPECT_EQ(s.trace.front().layer, s.start_layer);
  EXPECT_EQ(s.trace.back().layer, s.num_layers);
  // Each coarse layer runs at most iterations_per_layer iterations.
  for (int l = s.start_layer; l < s.num_layers; ++l) {
    EXPECT_LE(s.iterations_per_layer[static_cast<size_t>(l - 1)],
              RegistrationOptions().schedule.iterations_per_layer);
  }
  EXPECT_EQ(s.matched_points + s.unmatched_points, s.sampled_points);
  EXPECT_GT(s.matched_points, s.sampled_points * 8 / 10);
  EXPECT_LT(s.final_score, s.initial_score);
  EXPECT_GT(s.map_time_s, 0.0);
  EXPECT_GT(s.sampling_time_s, 0.0);
  EXPECT_GT(s.solve_time_s, 0.0);
  EXPECT_GE(s.total_time_s, s.map_time_s + s.sampling_time_s + s.solve_time_s);
  // Covariance: symmetric positive definite, small at a good solution.
  EXPECT_TRUE(s.covariance.isApprox(s.covariance.transpose(), 1e-9));
  const Eigen::SelfAdjointEigenSolver<Matrix6d> es(s.covariance);
  EXPECT_GT(es.eigenvalues().minCoeff(), 0.0);
  EXPECT_LT(std::sqrt(s.covariance(0, 0)), 0.05);
  EXPECT_TRUE(s.reference_from_input.isApprox(
      PoseVectorToIsometry(s.reference_from_input_xi)));
}

TEST(Registration, PaperScheduleRunsThreeIterationsPerLayer) {
  RegistrationOptions options;
  options.schedule.start_layer = 2;
  options.schedule.iterations_per_layer = 3;
  options.grid.num_layers = 4;
  options.grid.finest_cell_size_m = 0.0;  // The paper's q = 8, n = 4.
  const Isometry3d truth =
      PoseVectorToIsometry(PoseVectorFromDegrees(1, 0, 0, 0, 0, 3));
  const RegistrationSummary s =
      RegisterStreet(truth, Isometry3d::Identity(), options);
  ASSERT_TRUE(s.IsSolutionUsable()) << s.message;
  ASSERT_EQ(s.num_layers, 4);
  EXPECT_EQ(s.iterations_per_layer[0], 0);
  EXPECT_EQ(s.iterations_per_layer[1], 3);
  EXPECT_EQ(s.iterations_per_layer[2], 3);
  EXPECT_GE(s.iterations_per_layer[3], 1);
}

TEST(Registration, InvalidOptionsGiveFailureNotAbort) {
  const PointCloud cloud = testing::StreetScene(5000, 0.02, 5);
  RegistrationSummary summary;
  RegistrationOptions options;
  options.schedule.iterations_per_layer = 0;
  Register(options, cloud, cloud, Isometry3d::Identity(), &summary);
  EXPECT_EQ(summary.termination_type, TerminationType::FAILURE);
  EXPECT_NE(summary.message.find("iterations_per_layer"), std::string::npos)
      << summary.message;

  options = RegistrationOptions();
  options.objective.loss_scale = -1.0;
  Register(options, cloud, cloud, Isometry3d::Identity(), &summary);
  EXPECT_EQ(summary.termination_type, TerminationType::FAILURE);
  EXPECT_NE(summary.message.find("loss_scale"), std::string::npos)
      << summary.message;

  options = RegistrationOptions();
  options.sampling.random_fraction = 2.0;
  Register(options, cloud, cloud, Isometry3d::Identity(), &summary);
  EXPECT_EQ(summary.termination_type, TerminationType::FAILURE);
  EXPECT_NE(summary.message.find("random_fraction"), std::string::npos)
      << summary.message;
}

TEST(Registration, BadInputGivesFailureWithMessage) {
  const PointCloud cloud = testing::StreetScene(5000, 0.02, 6);
  RegistrationSummary summary;
  Register(RegistrationOptions(),
           cloud,
           PointCloud(),
           Isometry3d::Identity(),
           &summary);
  EXPECT_EQ(summary.termination_type, TerminationType::FAILURE);
  EXPECT_NE(summary.message.find("empty"), std::string::npos)
      << summary.message;

  Register(RegistrationOptions(),
           PointCloud(),
           cloud,
           Isometry3d::Identity(),
           &summary);
  EXPECT_EQ(summary.termination_type, TerminationType::FAILURE);
  EXPECT_NE(summary.message.find("reference"), std::string::npos)
      << summary.message;

  PointCloud with_nan = cloud;
  with_nan.Add(Eigen::Vector3d(0, std::nan(""), 0));
  Register(
      RegistrationOptions(), cloud, with_nan, Isometry3d::Identity(), &summary);
  EXPECT_EQ(summary.termination_type, TerminationType::FAILURE);
  EXPECT_NE(summary.message.find("non-finite"), std::string::npos)
      << summary.message;

  Isometry3d bad = Isometry3d::Identity();
  bad.translation().x() = std::nan("");
  Register(RegistrationOptions(), cloud, cloud, bad, &summary);
  EXPECT_EQ(summary.termination_type, TerminationType::FAILURE);
  EXPECT_NE(summary.message.find("initial guess"), std::string::npos)
      << summary.message;
}

TEST(Registration, DisjointCloudsAreReportedAsFailure) {
  // The input lies 1 km away from the map: no point is ever matched.
  const PointCloud reference = testing::StreetScene(5000, 0.02, 7);
  const PointCloud input = TransformCloud(
      PoseVectorToIsometry(PoseVectorFromDegrees(1000, 0, 0, 0, 0, 0)),
      reference);
  RegistrationSummary summary;
  Register(RegistrationOptions(),
           reference,
           input,
           Isometry3d::Identity(),
           &summary);
  EXPECT_EQ(summary.termination_type, TerminationType::FAILURE);
  EXPECT_NE(summary.message.find("occupied cell"), std::string::npos)
      << summary.message;
}

class RegistrationBackends
    : public ::testing::TestWithParam<std::tuple<LossType, int>> {};

TEST_P(RegistrationBackends, AllBackendsReachTheSameFinalScore) {
  // Same objective, same cells, same samples: Ceres, Newton and LM must end
  // at the same score and pose (compared on the score, as Ceres' SystemTest).
  // From identity on the full schedule, and from near the truth on the last
  // layer alone.
  const Isometry3d truth =
      PoseVectorToIsometry(PoseVectorFromDegrees(2.5, -1, 0.1, 0, 1, 12));
  RegistrationOptions options;
  options.objective.loss = std::get<0>(GetParam());
  options.schedule.start_layer = std::get<1>(GetParam());
  const Isometry3d initial =
      options.schedule.start_layer == 0
          ? PoseVectorToIsometry(PoseVectorFromDegrees(0.2, 0.1, 0, 0, 0, 1)) *
                truth
          : Isometry3d::Identity();
  options.schedule.step_tolerance = 1e-6;
  options.schedule.max_coarse_point_stride = 1;  // Same points on every layer.
  options.schedule.max_final_iterations = 60;
  std::vector<RegistrationSummary> results;
  for (BackendType backend : {BackendType::CERES,
                              BackendType::NEWTON,
                              BackendType::LEVENBERG_MARQUARDT}) {
    options.backend.type = backend;
    results.push_back(RegisterStreet(truth, initial, options));
    ASSERT_TRUE(results.back().IsSolutionUsable())
        << BackendTypeToString(backend) << ": " << results.back().message;
  }
  for (size_t b = 1; b < results.size(); ++b) {
    EXPECT_NEAR(results[b].final_score,
                results[0].final_score,
                1e-3 * results[0].final_score)
        << "backend " << b;
    EXPECT_LT(TranslationErrorM(results[b].reference_from_input,
                                results[0].reference_from_input),
              5e-3)
        << "backend " << b;
    EXPECT_LT(RotationErrorRad(results[b].reference_from_input,
                               results[0].reference_from_input),
              0.05 * kDegToRad)
        << "backend " << b;
  }
}

INSTANTIATE_TEST_SUITE_P(LossAndStartLayer,
                         RegistrationBackends,
                         ::testing::Combine(::testing::Values(LossType::NONE,
                                                              LossType::CAUCHY),
                                            ::testing::Values(1, 0)));

TEST(Registration, PrebuiltMapGivesTheSameResult) {
  const Isometry3d truth =
      PoseVectorToIsometry(PoseVectorFromDegrees(2, 1, 0, 0, 0, 8));
  const PointCloud reference = testing::StreetScene(40000, 0.02, 9);
  const PointCloud input =
      TransformCloud(truth.inverse(), testing::StreetScene(40000, 0.02, 10));
  const RegistrationOptions options;
  // The overload that builds the map drops the reference's returns near the
  // sensor first; the caller does it for a prebuilt map.
  RangeFilterSummary filtered;
  const PointCloud kept =
      FilterByRange(options.range_filter, reference, &filtered);
  ASSERT_GT(filtered.too_close, 0u);
  LayeredGrid map;
  std::string error;
  ASSERT_TRUE(LayeredGrid::Build(options.grid, kept, &map, &error)) << error;
  RegistrationSummary with_map, with_cloud;
  Register(options, map, input, Isometry3d::Identity(), &with_map);
  Register(options, reference, input, Isometry3d::Identity(), &with_cloud);
  ASSERT_TRUE(with_map.IsSolutionUsable() && with_cloud.IsSolutionUsable());
  EXPECT_TRUE(with_map.reference_from_input_xi.isApprox(
      with_cloud.reference_from_input_xi, 1e-9));
  EXPECT_EQ(with_map.map_time_s, 0.0);
  EXPECT_GT(with_cloud.map_time_s, 0.0);
}

}  // namespace
}  // namespace mlndt
