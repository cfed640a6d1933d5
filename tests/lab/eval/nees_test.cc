#include "lab/eval/nees.h"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <random>
#include <vector>

namespace mlndt {
namespace {

// A covariance with strong correlations (off-diagonal terms up to ~0.9 of
// the diagonal ones) and scales from 1e-4 to 1.
Matrix6d CorrelatedCovariance() {
  Matrix6d a;
  std::mt19937 rng(17);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) a(i, j) = normal(rng);
  Vector6d scales;
  scales << 1.0, 0.5, 0.1, 0.05, 0.02, 0.01;
  const Matrix6d c = scales.asDiagonal() *
                     (a * a.transpose() + 0.1 * Matrix6d::Identity()) *
                     scales.asDiagonal();
  return c;
}

// n errors drawn from N(0, C): e = L z with C = L L^T, z ~ N(0, I).
std::vector<Vector6d> Draw(const Matrix6d& c, int n, unsigned seed) {
  const Matrix6d l = c.llt().matrixL();
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<Vector6d> errors;
  for (int k = 0; k < n; ++k) {
    Vector6d z;
    for (int i = 0; i < 6; ++i) z(i) = normal(rng);
    errors.push_back(l * z);
  }
  return errors;
}

TEST(Nees, HandComputedNonDiagonal) {
  // C = [[2, 1], [1, 2]] on (tx, ty), identity elsewhere: C^-1 = [[2, -1],
  // [-1, 2]] / 3, so e = (1, 1, 0, 0, 0, 2) gives (2 - 2 + 2) / 3 + 4.
  Matrix6d c = Matrix6d::Identity();
  c(0, 0) = c(1, 1) = 2.0;
  c(0, 1) = c(1, 0) = 1.0;
  Vector6d e;
  e << 1, 1, 0, 0, 0, 2;
  EXPECT_NEAR(Nees(e, c), 2.0 / 3.0 + 4.0, 1e-12);
  // e = (1, -1, ...): (2 + 2 + 2) / 3 + 4.
  e(1) = -1;
  EXPECT_NEAR(Nees(e, c), 2.0 + 4.0, 1e-12);
}

TEST(ComputeNees, ErrorsFromTheCovarianceAverageTheDimension) {
  const Matrix6d c = CorrelatedCovariance();
  const std::vector<Vector6d> errors = Draw(c, 20000, 1);
  const std::vector<Matrix6d> covariances(errors.size(), c);
  NeesSummary summary;
  std::string error;
  ASSERT_TRUE(ComputeNees(errors, covariances, &summary, &error)) << error;
  ASSERT_EQ(summary.nees.size(), errors.size());
  EXPECT_EQ(summary.expected, 6.0);
  // Chi-square with 6 dof: variance 12, so the mean of 20000 has s.d. 0.025.
  EXPECT_NEAR(summary.mean, 6.0, 0.1);
  EXPECT_NEAR(summary.scale_factor, 1.0, 0.1 / 6.0);

  // Chi-square with 6 dof has variance 12. This also tells C from its
  // diagonal D, whose mean NEES is 6 as well (tr(D^-1 C) = 6) but whose
  // variance is 2 tr((D^-1 C)^2) > 12 when C has correlations.
  const auto variance = [](const std::vector<double>& v) {
    double mean = 0.0, squares = 0.0;
    for (double x : v) mean += x / v.size();
    for (double x : v) squares += (x - mean) * (x - mean);
    return squares / (v.size() - 1);
  };
  EXPECT_NEAR(variance(summary.nees), 12.0, 0.8);
  const Matrix6d diagonal = Matrix6d(c.diagonal().asDiagonal());
  NeesSummary diagonal_only;
  ASSERT_TRUE(ComputeNees(errors,
                          std::vector<Matrix6d>(errors.size(), diagonal),
                          &diagonal_only,
                          &error));
  EXPECT_GT(variance(diagonal_only.nees), 15.0);

  // Covariances 4x too small: NEES 4x too large, k = 4.
  NeesSummary small;
  ASSERT_TRUE(ComputeNees(
      errors, std::vector<Matrix6d>(errors.size(), 0.25 * c), &small, &error));
  EXPECT_NEAR(small.scale_factor, 4.0 * summary.scale_factor, 1e-9);
}

TEST(ComputeNeesAboutMean, ExpectsSixTimesNMinusOneOverN) {
  EXPECT_NEAR(ExpectedNeesAboutMean(20), 5.7, 1e-12);  // mlndt_covariance.
  EXPECT_NEAR(ExpectedNeesAboutMean(2), 3.0, 1e-12);
  const Matrix6d c = CorrelatedCovariance();
  Vector6d truth;
  truth << 1, 2, 3, 0.1, 0.2, 0.3;
  // 4000 groups of 5 samples about an unknown mean.
  double sum = 0.0;
  int groups = 0;
  for (unsigned g = 0; g < 4000; ++g) {
    std::vector<Vector6d> samples = Draw(c, 5, 100 + g);
    for (Vector6d& x : samples) x += truth;
    NeesSummary summary;
    std::string error;
    ASSERT_TRUE(ComputeNeesAboutMean(
        samples, std::vector<Matrix6d>(5, c), &summary, &error))
        << error;
    EXPECT_NEAR(summary.expected, 4.8, 1e-12);
    sum += summary.mean;
    ++groups;
  }
  EXPECT_NEAR(sum / groups, 4.8, 0.1);
  EXPECT_NEAR(NeesScaleFactor(sum / groups, 4.8), 1.0, 0.1 / 4.8);
}

TEST(ComputeNees, Failures) {
  NeesSummary summary;
  std::string error;
  const std::vector<Vector6d> errors(3, Vector6d::Ones());
  EXPECT_FALSE(ComputeNees(errors,
                           std::vector<Matrix6d>(2, Matrix6d::Identity()),
                           &summary,
                           &error));
  EXPECT_NE(error.find("3 errors but 2"), std::string::npos) << error;
  EXPECT_FALSE(ComputeNees({}, {}, &summary, &error));
  std::vector<Matrix6d> covariances(3, Matrix6d::Identity());
  covariances[1](2, 2) = -1.0;  // Not positive definite.
  EXPECT_FALSE(ComputeNees(errors, covariances, &summary, &error));
  EXPECT_NE(error.find("sample 1"), std::string::npos) << error;
  covariances[1] = Matrix6d::Identity();
  covariances[2](0, 1) = 0.5;  // Not symmetric.
  EXPECT_FALSE(ComputeNees(errors, covariances, &summary, &error));
  EXPECT_NE(error.find("sample 2"), std::string::npos) << error;
  EXPECT_FALSE(ComputeNeesAboutMean(
      {Vector6d::Zero()}, {Matrix6d::Identity()}, &summary, &error));
  EXPECT_NE(error.find("at least 2"), std::string::npos) << error;
}

}  // namespace
}  // namespace mlndt
