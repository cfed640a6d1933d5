#include "integrations/ros/core/ros_pose.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "mlndt/common/pose.h"
#include "tests/testing/eigen_near.h"

namespace mlndt {
namespace ros_core {
namespace {

using testing::EigenNear;

// The small rotation w with exp([w]x) = a b^-1 (a close to b).
Eigen::Vector3d RotationBetween(const Eigen::Matrix3d& a,
                                const Eigen::Matrix3d& b) {
  const Eigen::AngleAxisd d(a * b.transpose());
  return d.angle() * d.axis();
}

// Columns of d(t, w)/d(xi) against central differences of the rotation
// about the parent's axes, at poses with large angles (where the Euler
// rates and the fixed-axis rotation differ).
TEST(RosPose, JacobianMatchesFiniteDifferences) {
  for (const Vector6d& xi :
       {Vector6d((Vector6d() << 1, -2, 3, 0.3, -0.7, 2.1).finished()),
        Vector6d((Vector6d() << 0, 0, 0, -2.5, 1.2, -0.4).finished())}) {
    const Matrix6d jacobian = RosTangentFromPoseVectorJacobian(xi);
    Matrix6d numeric = Matrix6d::Constant(std::nan(""));
    const double h = 1e-6;
    for (int k = 0; k < 6; ++k) {
      Vector6d plus = xi, minus = xi;
      plus(k) += h;
      minus(k) -= h;
      const Isometry3d a = PoseVectorToIsometry(plus);
      const Isometry3d b = PoseVectorToIsometry(minus);
      numeric.block<3, 1>(0, k) = (a.translation() - b.translation()) / (2 * h);
      numeric.block<3, 1>(3, k) =
          RotationBetween(a.linear(), b.linear()) / (2 * h);
    }
    EXPECT_TRUE(EigenNear(jacobian, numeric, 1e-8));
  }
}

TEST(RosPose, CovarianceIsMappedAndUnknownIsMarked) {
  Matrix6d xi_covariance = Matrix6d::Zero();
  xi_covariance.diagonal() << 1, 2, 3, 0.1, 0.2, 0.3;
  xi_covariance(0, 5) = xi_covariance(5, 0) = 0.05;
  // At the identity the rotations about the axes are the Euler angles.
  const std::array<double, 36> at_identity =
      ToRosCovariance(Isometry3d::Identity(), xi_covariance, true);
  for (int r = 0; r < 6; ++r) {
    for (int c = 0; c < 6; ++c) {
      EXPECT_NEAR(at_identity[6 * r + c], xi_covariance(r, c), 1e-15);
    }
  }
  // Elsewhere J Sigma J^T, symmetric.
  Vector6d xi;
  xi << 0, 0, 0, 0.4, -0.3, 1.0;
  const Isometry3d pose = PoseVectorToIsometry(xi);
  const Matrix6d j = RosTangentFromPoseVectorJacobian(xi);
  const Matrix6d expected = j * xi_covariance * j.transpose();
  const std::array<double, 36> mapped =
      ToRosCovariance(pose, xi_covariance, true);
  for (int r = 0; r < 6; ++r) {
    for (int c = 0; c < 6; ++c) {
      EXPECT_NEAR(mapped[6 * r + c], expected(r, c), 1e-14);
      EXPECT_NEAR(mapped[6 * r + c], mapped[6 * c + r], 1e-14);
    }
  }
  // Unknown, or infinite along a degenerate direction: element 0 is -1.
  xi_covariance(2, 2) = std::numeric_limits<double>::infinity();
  for (const std::array<double, 36>& unknown :
       {ToRosCovariance(pose, xi_covariance, true),
        ToRosCovariance(pose, Matrix6d::Identity(), false)}) {
    EXPECT_EQ(unknown[0], -1.0);
    for (size_t i = 1; i < 36; ++i) EXPECT_EQ(unknown[i], 0.0) << i;
  }
}

// w >= 0 as in the tools' TUM files, and back to the same transform.
TEST(RosPose, QuaternionHasNonNegativeWAndRoundTrips) {
  Vector6d xi;
  xi << 1.5, -2, 0.25, 3.0, 0.2, -3.0;  // A rotation near pi.
  const Isometry3d pose = PoseVectorToIsometry(xi);
  const RosPose ros_pose = ToRosPose(pose);
  EXPECT_GE(ros_pose.orientation.w(), 0.0);
  EXPECT_EQ(ros_pose.position, pose.translation());
  const Eigen::Quaterniond eigen(pose.linear());
  EXPECT_EQ(std::abs(ros_pose.orientation.x()), std::abs(eigen.x()));
  EXPECT_TRUE(EigenNear(FromRosPose(ros_pose).matrix(), pose.matrix(), 1e-15));
}

}  // namespace
}  // namespace ros_core
}  // namespace mlndt
