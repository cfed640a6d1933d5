#include "lab/eval/umeyama.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>
#include <vector>

#include "tests/testing/eigen_near.h"

namespace mlndt {
namespace {

using testing::EigenNear;

Matrix3d Rz90() {
  Matrix3d r;
  r << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  return r;
}

// By hand: the four points (+-1, 0, 0), (0, +-1, 0) have mean 0 and
// sigma_x^2 = 1. Turned by 90 deg about z, doubled and moved by (5, 0, 1),
// the target has mean (5, 0, 1) and Sigma_xy = 2 Rz90 diag(1/2, 1/2, 0), so
// U D V^T gives R = Rz90, tr(D S) = 2 * (1/2 + 1/2) = 2, c = 2, t = (5, 0, 1).
TEST(UmeyamaAlignment, HandComputedSimilarity) {
  const std::vector<Vector3d> source = {
      {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
  std::vector<Vector3d> target;
  for (const Vector3d& x : source)
    target.push_back(2.0 * Rz90() * x + Vector3d(5, 0, 1));
  SimilarityTransform fit;
  std::string error;
  ASSERT_TRUE(UmeyamaAlignment(source, target, true, &fit, &error)) << error;
  EXPECT_TRUE(EigenNear(fit.rotation, Rz90(), 1e-12));
  EXPECT_NEAR(fit.scale, 2.0, 1e-12);
  EXPECT_TRUE(EigenNear(fit.translation, Vector3d(5, 0, 1), 1e-12));
  EXPECT_TRUE(EigenNear(fit * Vector3d(1, 0, 0), target[0], 1e-12));

  // Rigid: same rotation and, since the source mean is 0, same translation;
  // the scale stays 1.
  ASSERT_TRUE(UmeyamaAlignment(source, target, false, &fit, &error)) << error;
  EXPECT_TRUE(EigenNear(fit.rotation, Rz90(), 1e-12));
  EXPECT_EQ(fit.scale, 1.0);
  EXPECT_TRUE(EigenNear(fit.translation, Vector3d(5, 0, 1), 1e-12));
}

TEST(UmeyamaAlignment, MirroredPointsGiveARotationNotAReflection) {
  std::mt19937 rng(3);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<Vector3d> source, target;
  for (int i = 0; i < 30; ++i) {
    const Vector3d x(normal(rng), normal(rng), normal(rng));
    source.push_back(x);
    target.push_back(Vector3d(x.x(), x.y(), -x.z()));  // det(Sigma_xy) < 0.
  }
  SimilarityTransform fit;
  std::string error;
  ASSERT_TRUE(UmeyamaAlignment(source, target, true, &fit, &error)) << error;
  EXPECT_NEAR(fit.rotation.determinant(), 1.0, 1e-12);
  EXPECT_TRUE(EigenNear(
      fit.rotation * fit.rotation.transpose(), Matrix3d::Identity(), 1e-12));
}

TEST(UmeyamaAlignment, AgreesWithEigenOnNoisyPoints) {
  std::mt19937 rng(5);
  std::normal_distribution<double> normal(0.0, 1.0);
  const Eigen::Quaterniond q =
      Eigen::Quaterniond(normal(rng), normal(rng), normal(rng), normal(rng))
          .normalized();
  std::vector<Vector3d> source, target;
  Eigen::Matrix3Xd source_matrix(3, 50), target_matrix(3, 50);
  for (int i = 0; i < 50; ++i) {
    const Vector3d x(10 * normal(rng), 10 * normal(rng), normal(rng));
    const Vector3d y = 0.7 * (q * x) + Vector3d(1, -2, 3) +
                       0.05 * Vector3d(normal(rng), normal(rng), normal(rng));
    source.push_back(x);
    target.push_back(y);
    source_matrix.col(i) = x;
    target_matrix.col(i) = y;
  }
  for (bool with_scale : {false, true}) {
    SimilarityTransform fit;
    std::string error;
    ASSERT_TRUE(UmeyamaAlignment(source, target, with_scale, &fit, &error));
    const Eigen::Matrix4d eigen =
        Eigen::umeyama(source_matrix, target_matrix, with_scale);
    const double scale = eigen.block<3, 1>(0, 0).norm();
    EXPECT_NEAR(fit.scale, with_scale ? scale : 1.0, 1e-10);
    EXPECT_TRUE(
        EigenNear(fit.rotation, eigen.block<3, 3>(0, 0) / scale, 1e-10));
    EXPECT_TRUE(EigenNear(fit.translation, eigen.block<3, 1>(0, 3), 1e-9));
    if (with_scale) {
      EXPECT_NEAR(fit.scale, 0.7, 0.01);
      EXPECT_TRUE(EigenNear(fit.rotation, q.toRotationMatrix(), 0.01));
    }
  }
}

TEST(UmeyamaAlignment, RejectsTooFewMismatchedOrCoincidentPoints) {
  SimilarityTransform fit;
  std::string error;
  const std::vector<Vector3d> two = {{0, 0, 0}, {1, 0, 0}};
  EXPECT_FALSE(UmeyamaAlignment(two, two, false, &fit, &error));
  EXPECT_NE(error.find("at least 3"), std::string::npos) << error;
  const std::vector<Vector3d> three = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_FALSE(UmeyamaAlignment(three, two, false, &fit, &error));
  EXPECT_NE(error.find("3 source points but 2"), std::string::npos) << error;
  const std::vector<Vector3d> same(3, Vector3d(1, 2, 3));
  EXPECT_FALSE(UmeyamaAlignment(same, three, true, &fit, &error));
  EXPECT_NE(error.find("coincide"), std::string::npos) << error;
}

}  // namespace
}  // namespace mlndt
