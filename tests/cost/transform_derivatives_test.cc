#include "mlndt/cost/transform_derivatives.h"

#include <ceres/jet.h>
#include <gtest/gtest.h>

#include "mlndt/common/pose.h"

namespace mlndt {
namespace {

const Vector6d kXi = (Vector6d() << 0.4, -1.2, 0.3, 0.35, -0.6, 1.1).finished();
const Eigen::Vector3d kPoint(2.0, -3.5, 1.25);

TEST(TransformDerivatives, TransformMatchesEulerRotation) {
  const TransformDerivatives d(kXi);
  EXPECT_TRUE(
      d.Transform(kPoint).isApprox(TransformPoint(kXi.data(), kPoint), 1e-14));
}

TEST(TransformDerivatives, JacobianMatchesAutoDiff) {
  using Jet = ceres::Jet<double, 6>;
  Jet xi[6];
  for (int i = 0; i < 6; ++i) xi[i] = Jet(kXi(i), i);
  const Eigen::Matrix<Jet, 3, 1> x = TransformPoint(xi, kPoint);
  const Eigen::Matrix<double, 3, 6> jacobian =
      TransformDerivatives(kXi).Jacobian(kPoint);
  for (int r = 0; r < 3; ++r) {
    EXPECT_TRUE(jacobian.row(r).transpose().isApprox(x(r).v, 1e-12))
        << "row " << r;
  }
}

TEST(TransformDerivatives, SecondDerivativeMatchesFiniteDifferenceOfJacobian) {
  const Eigen::Vector3d w(0.7, -1.3, 2.1);
  const Matrix6d analytic =
      TransformDerivatives(kXi).WeightedSecondDerivative(kPoint, w);
  const double h = 1e-6;
  Matrix6d numeric;
  for (int j = 0; j < 6; ++j) {
    Vector6d plus = kXi, minus = kXi;
    plus(j) += h;
    minus(j) -= h;
    const Eigen::Matrix<double, 3, 6> jp =
        TransformDerivatives(plus).Jacobian(kPoint);
    const Eigen::Matrix<double, 3, 6> jm =
        TransformDerivatives(minus).Jacobian(kPoint);
    numeric.col(j) = ((jp - jm) / (2 * h)).transpose() * w;
  }
  EXPECT_TRUE(analytic.isApprox(numeric, 1e-7)) << analytic << "\n\n"
                                                << numeric;
  EXPECT_TRUE(analytic.topRows<3>().isZero());  // No translation terms.
  const double angle_block = analytic.bottomRightCorner<3, 3>().norm();
  EXPECT_GT(angle_block, 0.1);
}

}  // namespace
}  // namespace mlndt
