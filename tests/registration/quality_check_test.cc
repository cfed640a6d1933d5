// The verdict (quality_check.h) on scenes whose answer is known: a plane, a
// corridor and a line leave directions free and are DEGENERATE (with an
// infinite covariance along them); a street scene is constrained; a pose
// far from the truth fails the fit check; the rules by hand.

#include "mlndt/registration/quality_check.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "mlndt/common/pose.h"
#include "mlndt/registration/registration.h"
#include "tests/testing/synthetic_scene.h"

namespace mlndt {
namespace {

RegistrationSummary RegisterShifted(
    const PointCloud& reference,
    const PointCloud& second_sample,
    const Eigen::Vector3d& shift,
    const RegistrationOptions& options = RegistrationOptions()) {
  Isometry3d truth = Isometry3d::Identity();
  truth.translation() = shift;
  RegistrationSummary summary;
  Register(options,
           reference,
           TransformCloud(truth.inverse(), second_sample),
           Isometry3d::Identity(),
           &summary);
  return summary;
}

TEST(QualityCheck, APlaneIsDegenerateAlongItself) {
  const Eigen::Vector3d low(-20, -20, -0.01), high(20, 20, 0.01);
  const RegistrationSummary s =
      RegisterShifted(testing::UniformBox(low, high, 40000, 1),
                      testing::UniformBox(low, high, 40000, 2),
                      {0.5, 0.3, 0.1});
  EXPECT_EQ(s.termination_type, TerminationType::DEGENERATE) << s.message;
  EXPECT_FALSE(s.IsSolutionUsable());
  EXPECT_LT(s.constraints.constraint_ratio, 0.01);
  // Free: x, y and the turn about z; the covariance says so.
  EXPECT_EQ(s.constraints.degenerate_directions.size(), 3u) << s.message;
  EXPECT_TRUE(std::isinf(s.covariance(0, 0)));
  EXPECT_TRUE(std::isinf(s.covariance(1, 1)));
  EXPECT_TRUE(std::isinf(s.covariance(5, 5)));
  EXPECT_TRUE(std::isfinite(s.covariance(2, 2)));  // Height is constrained.
  // The translation the plane constrains most is its normal; the weakest
  // lies in it.
  EXPECT_GT(std::abs(s.constraints.weakest_translations(2, 2)), 0.99);
  EXPECT_LT(std::abs(s.constraints.weakest_translations(2, 0)), 0.01);
  EXPECT_NE(s.message.find("degenerate"), std::string::npos) << s.message;
  EXPECT_NE(s.FullReport().find("inf"), std::string::npos) << s.FullReport();
}

TEST(QualityCheck, ACorridorIsDegenerateAlongItsLength) {
  const auto corridor = [](uint32_t seed) {
    return testing::SlabCorridor(seed);
  };
  const RegistrationSummary s =
      RegisterShifted(corridor(1), corridor(2), {1.0, 0.2, 0.0});
  EXPECT_EQ(s.termination_type, TerminationType::DEGENERATE) << s.message;
  // Free: the corridor's axis, x (the roll about it, with a 2 m lever
  // against a 17 m RMS range, is weak too).
  ASSERT_GE(s.constraints.degenerate_directions.size(), 1u) << s.message;
  EXPECT_GT(std::abs(s.constraints.degenerate_directions[0](0)), 0.99);
  EXPECT_NE(s.message.find("translation along (1.00, 0.00, 0.00)"),
            std::string::npos)
      << s.message;
  EXPECT_TRUE(std::isinf(s.covariance(0, 0)));
  EXPECT_TRUE(std::isfinite(s.covariance(1, 1)));
  // With the rotation held, the weakest translation is the axis as well.
  EXPECT_GT(std::abs(s.constraints.weakest_translations(0, 0)), 0.99);
}

// Issue 22's corridor: two walls and a floor, a 100 m reference and 40 m of
// it as input, sampled at 8000 and at 45000 points. Its length is free at
// both densities, with the default options: the probe of weak directions
// (on by default) finds it flat (0.99-1.00 of the inliers kept one cell
// along it), so the decision does not depend on how many points there are;
// with the probe off (the default before), 8000 points were CONVERGENCE.
class SparseCorridor : public ::testing::TestWithParam<int> {};

TEST_P(SparseCorridor, IsDegenerateAlongItsLengthAtAnyDensity) {
  const int input_points = GetParam();
  const PointCloud reference =  // The same density.
      testing::Corridor(50.0, input_points * 5 / 2, 1);
  const RegistrationSummary s = RegisterShifted(
      reference, testing::Corridor(20.0, input_points, 2), {1.0, 0.1, 0.0});
  EXPECT_EQ(s.termination_type, TerminationType::DEGENERATE) << s.message;
  EXPECT_NE(s.message.find("translation along (1.00, "), std::string::npos)
      << s.message;
  // Unknown along the corridor: unbounded, or at least a metre.
  EXPECT_GE(s.covariance(0, 0), 1.0) << s.FullReport();
  EXPECT_LT(s.covariance(1, 1), 0.01) << s.FullReport();
}

INSTANTIATE_TEST_SUITE_P(QualityCheck,
                         SparseCorridor,
                         ::testing::Values(8000, 45000));

// Flat ground as a spinning LiDAR 1.73 m above it sees it: 64 rings at
// elevations -24.9 to -2 deg (as KITTI's HDL-64), 0.5 deg apart in azimuth,
// within 40 m, 1 cm range noise, in the sensor's frame. Beyond a few metres
// one ring crosses a cell, so the cell is thin across the ring as well as
// across the ground.
PointCloud RingScannedGround(uint32_t seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 0.01);
  PointCloud cloud;
  for (int ring = 0; ring < 64; ++ring) {
    const double elevation = (-24.9 + ring * 22.9 / 63.0) * kDegToRad;
    const double range = 1.73 / std::sin(-elevation);
    if (range * std::cos(elevation) > 40.0) continue;
    for (int step = 0; step < 720; ++step) {
      const double azimuth = step * 0.5 * kDegToRad;
      const Eigen::Vector3d ray(std::cos(elevation) * std::cos(azimuth),
                                std::cos(elevation) * std::sin(azimuth),
                                std::sin(elevation));
      cloud.Add((range + noise(rng)) * ray);
    }
  }
  return cloud;
}

// The rings are where the sensor was, not where the ground is: in its own
// frame a flat ground looks the same from anywhere at the same height, so
// the two scans here (noise seeds 1 and 2) are also two scans from poses
// 0.8 m apart, and they fit best where their rings coincide, at no motion.
// A ring crossing a cell makes it thin across the ring too, but that direction
// is the scan pattern's, not the surface's: such line cells do not count as a
// constraint (quality_check.h), and the ground leaves x, y and the turn about z
// free, as it does when sampled uniformly (APlaneIsDegenerateAlongItself).
// Counting them, only the turn about z was free and the result at no motion
// could pass.
TEST(QualityCheck, AGroundScannedInRingsIsDegenerateAlongItself) {
  RegistrationSummary s;
  Register(RegistrationOptions(),
           RingScannedGround(1),
           RingScannedGround(2),
           Isometry3d::Identity(),
           &s);
  EXPECT_EQ(s.termination_type, TerminationType::DEGENERATE) << s.message;
  EXPECT_EQ(s.constraints.degenerate_directions.size(), 3u) << s.message;
  EXPECT_TRUE(std::isinf(s.covariance(0, 0))) << s.FullReport();
  EXPECT_TRUE(std::isinf(s.covariance(1, 1))) << s.FullReport();
  EXPECT_TRUE(std::isfinite(s.covariance(2, 2))) << s.FullReport();
}

TEST(QualityCheck, AStreetSceneIsConstrainedAndConverges) {
  const RegistrationSummary s =
      RegisterShifted(testing::StreetScene(60000, 0.02, 1),
                      testing::StreetScene(60000, 0.02, 2),
                      {0.4, 0.2, 0.0});
  EXPECT_EQ(s.termination_type, TerminationType::CONVERGENCE) << s.message;
  EXPECT_GT(s.constraints.constraint_ratio, 0.05);
  EXPECT_TRUE(s.constraints.degenerate_directions.empty());
  EXPECT_TRUE(s.covariance.allFinite());
  EXPECT_LT(s.reference_from_input.translation().x() - 0.4, 0.02);
}

// The street scene's length is a weak but real constraint (cross walls
// every 16 m, car fronts, poles: a few percent of the surface): one cell
// along it loses 7-17 % of the inliers, whatever the density, and the
// probe (on by default) does not call it flat. With the probe's former
// setting (max_flatness 0.8) these right results were DEGENERATE.
class StreetDensity : public ::testing::TestWithParam<int> {};

TEST_P(StreetDensity, IsConstrainedAlongItsLengthAtAnyDensity) {
  const int n = GetParam();  // Input points; the map has at least 20000.
  const RegistrationSummary s =
      RegisterShifted(testing::StreetScene(std::max(n, 20000), 0.02, 1),
                      testing::StreetScene(n, 0.02, 2),
                      {0.4, 0.2, 0.0});
  EXPECT_EQ(s.termination_type, TerminationType::CONVERGENCE) << s.message;
  EXPECT_NEAR(s.reference_from_input.translation().x(), 0.4, 0.05);
  EXPECT_NEAR(s.reference_from_input.translation().y(), 0.2, 0.05);
  // The probe ran (flatness is 0 when it is off) and found nothing flat.
  const QualityCheckOptions defaults;
  EXPECT_GT(s.constraints.flatness, 0.0) << s.FullReport();
  EXPECT_LT(s.constraints.flatness, defaults.max_flatness) << s.FullReport();
  EXPECT_EQ(s.constraints.flat_directions, 0);
}

INSTANTIATE_TEST_SUITE_P(QualityCheck,
                         StreetDensity,
                         ::testing::Values(5000, 20000, 60000));

TEST(QualityCheck, RulesByHand) {
  QualityCheckOptions options;
  ConstraintAnalysis constrained;
  constrained.constraint_ratio = 0.2;
  FitQuality good;
  good.inlier_fraction = 0.6;
  good.mean_score = 7.0;
  good.median_distance = 2.5;
  good.points = 2000;
  std::string message;
  EXPECT_EQ(CheckQuality(options,
                         TerminationType::NO_CONVERGENCE,
                         good,
                         constrained,
                         &message),
            TerminationType::NO_CONVERGENCE);
  FitQuality few = good;
  few.inlier_fraction = options.min_inlier_fraction - 0.01;
  EXPECT_EQ(
      CheckQuality(
          options, TerminationType::CONVERGENCE, few, constrained, &message),
      TerminationType::LOW_QUALITY);
  EXPECT_NE(message.find("inliers"), std::string::npos) << message;
  FitQuality few_points = good;
  few_points.points = options.min_fit_points - 1;
  EXPECT_EQ(CheckQuality(options,
                         TerminationType::CONVERGENCE,
                         few_points,
                         constrained,
                         &message),
            TerminationType::LOW_QUALITY);
  EXPECT_NE(message.find("too few"), std::string::npos) << message;
  FitQuality far = good;
  far.median_distance = options.max_median_distance + 0.1;
  EXPECT_EQ(
      CheckQuality(
          options, TerminationType::CONVERGENCE, far, constrained, &message),
      TerminationType::LOW_QUALITY);
  EXPECT_NE(message.find("median Mahalanobis distance"), std::string::npos)
      << message;
  // The mean score is off by default (it counts the points outside the
  // overlap) and judges when set.
  FitQuality spread = good;
  spread.mean_score = 50.0;
  EXPECT_EQ(
      CheckQuality(
          options, TerminationType::CONVERGENCE, spread, constrained, &message),
      TerminationType::CONVERGENCE);
  QualityCheckOptions with_mean = options;
  with_mean.max_mean_score = 11.0;
  EXPECT_EQ(CheckQuality(with_mean,
                         TerminationType::CONVERGENCE,
                         spread,
                         constrained,
                         &message),
            TerminationType::LOW_QUALITY);
  EXPECT_NE(message.find("mean score"), std::string::npos) << message;
  ConstraintAnalysis free = constrained;
  free.degenerate_directions.push_back(Vector6d::Unit(5));
  EXPECT_EQ(
      CheckQuality(options, TerminationType::CONVERGENCE, good, free, &message),
      TerminationType::DEGENERATE);
  EXPECT_NE(message.find("rotation about (0.00, 0.00, 1.00)"),
            std::string::npos)
      << message;
  options.enabled = false;
  EXPECT_EQ(
      CheckQuality(options, TerminationType::CONVERGENCE, far, free, &message),
      TerminationType::CONVERGENCE);
}

TEST(QualityCheckOptions, RangesAreChecked) {
  std::string error;
  EXPECT_TRUE(QualityCheckOptions().IsValid(&error)) << error;
  QualityCheckOptions options;
  options.inlier_gate = 0.0;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_NE(error.find("inlier_gate"), std::string::npos);
  options = QualityCheckOptions();
  options.max_mean_score = std::nan("");
  EXPECT_FALSE(options.IsValid(&error));
  options = QualityCheckOptions();
  options.max_median_distance = 0.0;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_NE(error.find("max_median_distance"), std::string::npos) << error;
  options = QualityCheckOptions();
  options.min_constraint_ratio = 1.0;
  EXPECT_FALSE(options.IsValid(&error));
}

}  // namespace
}  // namespace mlndt
