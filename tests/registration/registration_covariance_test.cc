// Is RegistrationSummary::covariance (2 H^-1 of the Gauss-Newton Hessian of
// the final ML-NDT score) a consistent estimate of the pose error? Checked on
// the synthetic street, where the truth and the noise are known: every trial
// draws a fresh reference and input scan (independent noise), starts from its
// own perturbed guess and samples with its own seed, and the normalised
// estimation error squared NEES = e^T P^-1 e (e = xi - xi_true in the pose
// vector of Eq. 11) should average 6 (6 DoF). lab/programs/mlndt_covariance
// does the same on real pairs, where the truth is not known well enough.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "mlndt/common/pose.h"
#include "mlndt/registration/registration.h"
#include "tests/testing/synthetic_scene.h"

namespace mlndt {
namespace {

struct NoiseCase {
  double noise_m;       // Per-axis Gaussian noise of every scan point.
  double min_k, max_k;  // Accepted range of k = mean NEES / 6.
};

struct Statistics {
  int runs = 0;
  double mean_nees = 0.0;
  Vector6d error_rms = Vector6d::Zero();      // sqrt(mean e_i^2).
  Vector6d predicted_std = Vector6d::Zero();  // sqrt(mean P_ii).
};

Statistics RunTrials(double noise_m, int trials) {
  const Isometry3d truth = PoseVectorToIsometry(
      PoseVectorFromDegrees(1.2, -0.4, 0.05, 0.5, -0.3, 3.0));
  const Vector6d truth_xi = IsometryToPoseVector(truth);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  RegistrationOptions options;
  Statistics stats;
  for (int t = 0; t < trials; ++t) {
    const PointCloud reference =
        testing::StreetScene(60000, noise_m, 1000 + 2 * t);
    const PointCloud input = TransformCloud(
        truth.inverse(), testing::StreetScene(60000, noise_m, 1001 + 2 * t));
    // Within +-0.5 m and +-5 deg of the truth.
    Vector6d offset;
    for (int a = 0; a < 3; ++a) offset(a) = 0.5 * unit(rng);
    for (int a = 3; a < 6; ++a) offset(a) = 5.0 * kDegToRad * unit(rng);
    options.sampling.seed = 1 + static_cast<uint64_t>(t);
    RegistrationSummary summary;
    Register(options,
             reference,
             input,
             PoseVectorToIsometry(offset) * truth,
             &summary);
    EXPECT_TRUE(summary.IsSolutionUsable()) << summary.message;
    if (!summary.IsSolutionUsable()) continue;
    const Vector6d e = summary.reference_from_input_xi - truth_xi;
    stats.mean_nees += e.dot(summary.covariance.ldlt().solve(e));
    stats.error_rms += e.cwiseAbs2();
    stats.predicted_std += summary.covariance.diagonal();
    ++stats.runs;
  }
  if (stats.runs == 0) return stats;
  stats.mean_nees /= stats.runs;
  stats.error_rms = (stats.error_rms / stats.runs).cwiseSqrt();
  stats.predicted_std = (stats.predicted_std / stats.runs).cwiseSqrt();
  return stats;
}

class RegistrationCovariance : public ::testing::TestWithParam<NoiseCase> {};

// Measured with these 20 trials (k = mean NEES / 6; 5 mm and 1 cm with the
// cases added for the run): noise 5 mm k = 0.49, 1 cm 1.09, 2 cm 0.92,
// 5 cm 3.29. The predicted covariance hardly follows the
// noise (0.92 -> 1.08 mm on x from 2 to 5 cm): the cell covariances are set
// by the cell shapes and the eigenvalue floors (1 % of the largest, 1e-3 m^2),
// not by the noise. With the default floors it is consistent for the 1-2 cm
// noise of a LiDAR, conservative below and optimistic above. (Floors of 0.1 %
// and 1e-4 m^2 made it follow the noise more, but optimistic: k = 2.6 at 2 cm.)
TEST_P(RegistrationCovariance, NeesMatchesSixDegreesOfFreedom) {
  const NoiseCase& c = GetParam();
  const Statistics stats = RunTrials(c.noise_m, 20);
  ASSERT_EQ(stats.runs, 20);
  const double k = stats.mean_nees / 6.0;
  std::printf("noise %.3f m: mean NEES %.2f (k = %.2f)\n",
              c.noise_m,
              stats.mean_nees,
              k);
  std::printf(
      "  error rms  t [mm] %.2f %.2f %.2f  angles [mdeg] %.2f %.2f %.2f\n",
      stats.error_rms(0) * 1e3,
      stats.error_rms(1) * 1e3,
      stats.error_rms(2) * 1e3,
      stats.error_rms(3) * kRadToDeg * 1e3,
      stats.error_rms(4) * kRadToDeg * 1e3,
      stats.error_rms(5) * kRadToDeg * 1e3);
  std::printf(
      "  predicted  t [mm] %.2f %.2f %.2f  angles [mdeg] %.2f %.2f %.2f\n",
      stats.predicted_std(0) * 1e3,
      stats.predicted_std(1) * 1e3,
      stats.predicted_std(2) * 1e3,
      stats.predicted_std(3) * kRadToDeg * 1e3,
      stats.predicted_std(4) * kRadToDeg * 1e3,
      stats.predicted_std(5) * kRadToDeg * 1e3);
  EXPECT_GE(k, c.min_k);
  EXPECT_LE(k, c.max_k);
  // Every axis is predicted within a factor of 4 of its actual error.
  for (int a = 0; a < 6; ++a) {
    EXPECT_LT(stats.error_rms(a), 4.0 * stats.predicted_std(a)) << "axis " << a;
    EXPECT_GT(stats.error_rms(a), 0.25 * stats.predicted_std(a))
        << "axis " << a;
  }
}

INSTANTIATE_TEST_SUITE_P(StreetScene,
                         RegistrationCovariance,
                         ::testing::Values(NoiseCase{0.02, 0.5, 2.0},
                                           NoiseCase{0.05, 1.5, 6.0}));

}  // namespace
}  // namespace mlndt
