#include "mlndt/common/pose.h"

#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "tests/testing/eigen_near.h"

namespace mlndt {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

using testing::EigenNear;

// Rx(alpha) Ry(beta) Rz(gamma) built from elementary rotations (Eq. 7).
Matrix3d ElementaryProduct(double alpha, double beta, double gamma) {
  return (Eigen::AngleAxisd(alpha, Eigen::Vector3d::UnitX()) *
          Eigen::AngleAxisd(beta, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(gamma, Eigen::Vector3d::UnitZ()))
      .toRotationMatrix();
}

// A random pose vector with |alpha|, |gamma| < pi and |beta| < pi/2 - 0.01.
Vector6d RandomPoseVector(std::mt19937* rng) {
  std::uniform_real_distribution<double> translation(-5.0, 5.0);
  std::uniform_real_distribution<double> angle(-M_PI + 1e-3, M_PI - 1e-3);
  std::uniform_real_distribution<double> tilt(-M_PI / 2 + 0.01,
                                              M_PI / 2 - 0.01);
  Vector6d xi;
  xi << translation(*rng), translation(*rng), translation(*rng), angle(*rng),
      tilt(*rng), angle(*rng);
  return xi;
}

// A uniformly random rotation (normalised Gaussian 4-vector), seeded.
Eigen::Quaterniond RandomRotation(std::mt19937* rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::Quaterniond q(normal(*rng), normal(*rng), normal(*rng), normal(*rng));
  q.normalize();
  return q;
}

TEST(EulerRotation, EqualsProductOfElementaryRotations) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI);
  for (int trial = 0; trial < 50; ++trial) {
    const double a = angle(rng), b = angle(rng), g = angle(rng);
    EXPECT_TRUE(
        EigenNear(EulerRotation(a, b, g), ElementaryProduct(a, b, g), 1e-14))
        << "alpha " << a << " beta " << b << " gamma " << g;
  }
  // The order matters: Rx Ry Rz is not Rz Ry Rx.
  const Matrix3d reversed = (Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()) *
                             Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitY()) *
                             Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX()))
                                .toRotationMatrix();
  EXPECT_GT((EulerRotation(0.1, 0.2, 0.3) - reversed).norm(), 1e-2);
}

TEST(EulerRotation, SingleAxisRotationsActOnTheRightAxes) {
  // Rx(90 deg) maps y to z; Ry(90 deg) maps z to x; Rz(90 deg) maps x to y.
  EXPECT_TRUE(EigenNear(EulerRotation(M_PI / 2, 0.0, 0.0) * Vector3d::UnitY(),
                        Vector3d::UnitZ(),
                        1e-15));
  EXPECT_TRUE(EigenNear(EulerRotation(0.0, M_PI / 2, 0.0) * Vector3d::UnitZ(),
                        Vector3d::UnitX(),
                        1e-15));
  EXPECT_TRUE(EigenNear(EulerRotation(0.0, 0.0, M_PI / 2) * Vector3d::UnitX(),
                        Vector3d::UnitY(),
                        1e-15));
}

TEST(EulerRotation, IsOrthonormalWithUnitDeterminant) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI);
  for (int trial = 0; trial < 50; ++trial) {
    const Matrix3d r = EulerRotation(angle(rng), angle(rng), angle(rng));
    EXPECT_TRUE(EigenNear(r.transpose() * r, Matrix3d::Identity(), 1e-14));
    EXPECT_NEAR(r.determinant(), 1.0, 1e-14);
  }
}

TEST(EulerRotation, JetScalarPartEqualsDoubleVersion) {
  using Jet = ceres::Jet<double, 3>;
  const Eigen::Matrix<Jet, 3, 3> r =
      EulerRotation(Jet(0.4, 0), Jet(-0.7, 1), Jet(1.9, 2));
  Matrix3d scalar;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) scalar(i, j) = r(i, j).a;
  }
  EXPECT_TRUE(EigenNear(scalar, EulerRotation(0.4, -0.7, 1.9), 1e-15));
}

TEST(PoseVector, VectorToIsometryToVectorRoundTrip) {
  std::mt19937 rng(3);
  for (int trial = 0; trial < 200; ++trial) {
    const Vector6d xi = RandomPoseVector(&rng);
    const Isometry3d transform = PoseVectorToIsometry(xi);
    EXPECT_TRUE(EigenNear(
        transform.linear(), ElementaryProduct(xi(3), xi(4), xi(5)), 1e-14));
    EXPECT_TRUE(EigenNear(transform.translation(), xi.head<3>(), 0.0));
    Vector6d back = Vector6d::Constant(kNaN);
    back = IsometryToPoseVector(transform);
    EXPECT_TRUE(EigenNear(back, xi, 1e-10)) << "trial " << trial;
  }
}

TEST(PoseVector, IsometryToVectorToIsometryRoundTrip) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> translation(-100.0, 100.0);
  for (int trial = 0; trial < 200; ++trial) {
    Isometry3d transform = Isometry3d::Identity();
    transform.linear() = RandomRotation(&rng).toRotationMatrix();
    transform.translation() =
        Vector3d(translation(rng), translation(rng), translation(rng));
    const Vector6d xi = IsometryToPoseVector(transform);
    ASSERT_TRUE(xi.allFinite());
    EXPECT_LE(std::abs(xi(4)), M_PI / 2);
    EXPECT_LE(std::abs(xi(3)), M_PI);
    EXPECT_LE(std::abs(xi(5)), M_PI);
    const Isometry3d back = PoseVectorToIsometry(xi);
    EXPECT_TRUE(EigenNear(back.matrix(), transform.matrix(), 1e-10))
        << "trial " << trial;
  }
}

TEST(TransformPoint, DoubleEqualsIsometryApplied) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> coordinate(-20.0, 20.0);
  for (int trial = 0; trial < 50; ++trial) {
    const Vector6d xi = RandomPoseVector(&rng);
    const Vector3d x(coordinate(rng), coordinate(rng), coordinate(rng));
    Vector3d transformed = Vector3d::Constant(kNaN);
    transformed = TransformPoint(xi.data(), x);
    // x' = R x + t (Eq. 6): rotation first, then translation.
    const Vector3d expected =
        ElementaryProduct(xi(3), xi(4), xi(5)) * x + xi.head<3>();
    EXPECT_TRUE(EigenNear(transformed, expected, 1e-12));
    EXPECT_TRUE(EigenNear(transformed, PoseVectorToIsometry(xi) * x, 1e-12));
  }
}

TEST(TransformPoint, JetDerivativeEqualsFiniteDifferences) {
  using Jet = ceres::Jet<double, 6>;
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> coordinate(-10.0, 10.0);
  constexpr double kStep = 1e-6;
  for (int trial = 0; trial < 20; ++trial) {
    const Vector6d xi = RandomPoseVector(&rng);
    const Vector3d x(coordinate(rng), coordinate(rng), coordinate(rng));
    Jet xi_jet[6];
    for (int i = 0; i < 6; ++i) xi_jet[i] = Jet(xi(i), i);
    const Eigen::Matrix<Jet, 3, 1> transformed = TransformPoint(xi_jet, x);
    Eigen::Matrix<double, 3, 6> jacobian =
        Eigen::Matrix<double, 3, 6>::Constant(kNaN);
    Vector3d value = Vector3d::Constant(kNaN);
    for (int r = 0; r < 3; ++r) {
      jacobian.row(r) = transformed(r).v.transpose();
      value(r) = transformed(r).a;
    }
    EXPECT_TRUE(EigenNear(value, TransformPoint(xi.data(), x), 1e-12));

    Eigen::Matrix<double, 3, 6> numeric;
    for (int i = 0; i < 6; ++i) {
      Vector6d plus = xi, minus = xi;
      plus(i) += kStep;
      minus(i) -= kStep;
      numeric.col(i) =
          (TransformPoint(plus.data(), x) - TransformPoint(minus.data(), x)) /
          (2.0 * kStep);
    }
    EXPECT_TRUE(EigenNear(jacobian, numeric, 1e-7)) << "trial " << trial;
    // The translation columns are exactly the identity.
    EXPECT_TRUE(EigenNear(jacobian.leftCols<3>(), Matrix3d::Identity(), 0.0));
  }
}

TEST(PoseErrors, RotationErrorOfKnownRelativeRotation) {
  const Vector3d axis = Vector3d(1.0, -2.0, 0.5).normalized();
  Isometry3d a = Isometry3d::Identity();
  a.linear() = EulerRotation(0.4, -0.3, 1.2);
  a.translation() = Vector3d(1, 2, 3);
  Isometry3d b = a;
  b.linear() = a.linear() * Eigen::AngleAxisd(0.25, axis).toRotationMatrix();
  b.translation() = Vector3d(-4, 0, 7);  // Translation does not matter.
  EXPECT_NEAR(RotationErrorRad(a, b), 0.25, 1e-12);
  EXPECT_NEAR(RotationErrorRad(b, a), 0.25, 1e-12);
  EXPECT_NEAR(RotationErrorRad(a, a), 0.0, 1e-12);
  // A left-multiplied relative rotation gives the same angle.
  Isometry3d c = a;
  c.linear() = Eigen::AngleAxisd(2.5, axis).toRotationMatrix() * a.linear();
  EXPECT_NEAR(RotationErrorRad(a, c), 2.5, 1e-12);
  // Angles above pi wrap: 3.5 rad about an axis is 2pi - 3.5 about its
  // opposite.
  Isometry3d d = Isometry3d::Identity();
  d.linear() = Eigen::AngleAxisd(3.5, axis).toRotationMatrix();
  EXPECT_NEAR(
      RotationErrorRad(Isometry3d::Identity(), d), 2.0 * M_PI - 3.5, 1e-12);
}

TEST(PoseErrors, TranslationErrorOfKnownOffset) {
  Isometry3d a = Isometry3d::Identity();
  a.linear() = EulerRotation(0.1, 0.2, 0.3);
  a.translation() = Vector3d(1, 2, 3);
  Isometry3d b = Isometry3d::Identity();  // Rotation does not matter.
  b.translation() = Vector3d(4, 6, 3);
  EXPECT_NEAR(TranslationErrorM(a, b), 5.0, 1e-15);
  EXPECT_NEAR(TranslationErrorM(b, a), 5.0, 1e-15);
  EXPECT_EQ(TranslationErrorM(a, a), 0.0);
}

TEST(PoseVector, FromDegrees) {
  Vector6d xi = Vector6d::Constant(kNaN);
  xi = PoseVectorFromDegrees(0.3, -0.2, 0.1, 90.0, -45.0, 180.0);
  Vector6d expected;
  expected << 0.3, -0.2, 0.1, M_PI / 2, -M_PI / 4, M_PI;
  EXPECT_TRUE(EigenNear(xi, expected, 1e-15));
  EXPECT_NEAR(kDegToRad * kRadToDeg, 1.0, 1e-15);
  EXPECT_NEAR(30.0 * kDegToRad, M_PI / 6, 1e-15);
}

}  // namespace
}  // namespace mlndt

namespace mlndt {
namespace {

TEST(PoseVector, GimbalLockRoundTripsTheRotation) {
  for (double beta : {M_PI / 2, -M_PI / 2}) {
    Isometry3d t = Isometry3d::Identity();
    t.linear() = (Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()) *
                  Eigen::AngleAxisd(beta, Eigen::Vector3d::UnitY()) *
                  Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()))
                     .toRotationMatrix();
    const Vector6d xi = IsometryToPoseVector(t);
    EXPECT_NEAR(xi(4), beta, 1e-9);
    EXPECT_LT(RotationErrorRad(t, PoseVectorToIsometry(xi)), 1e-9);
  }
}

}  // namespace
}  // namespace mlndt
