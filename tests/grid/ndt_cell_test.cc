#include "mlndt/grid/ndt_cell.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

namespace mlndt {
namespace {

// Section 4.1 exactly: the relative floor only.
CellRegularization Paper() {
  CellRegularization r;
  r.min_eigenvalue_m2 = 0.0;
  return r;
}

Eigen::Matrix3d NonDiagonalCovariance() {
  Eigen::Matrix3d a;
  a << 2.0, 0.7, -0.3,  //
      0.7, 1.0, 0.2,    //
      -0.3, 0.2, 0.5;
  return a;
}

TEST(NdtCell, WhiteningSatisfiesWtWEqualsInverseCovariance) {
  NdtCell cell;
  ASSERT_TRUE(MakeNdtCell(
      10, Eigen::Vector3d(1, 2, 3), NonDiagonalCovariance(), Paper(), &cell));
  const Eigen::Matrix3d inverse = NonDiagonalCovariance().inverse();
  EXPECT_TRUE(
      (cell.whitening.transpose() * cell.whitening).isApprox(inverse, 1e-12));
  EXPECT_TRUE(cell.information.isApprox(inverse, 1e-12));
  // ||W e||^2 = e^T C^-1 e for an arbitrary e (Eq. 10).
  const Eigen::Vector3d e(0.3, -1.2, 0.8);
  EXPECT_NEAR((cell.whitening * e).squaredNorm(), e.dot(inverse * e), 1e-12);
  // The whitening matrix is not diagonal for a correlated covariance.
  EXPECT_GT(std::abs(cell.whitening(0, 1)) + std::abs(cell.whitening(1, 0)),
            1e-3);
}

TEST(NdtCell, RegularisesNearlySingularCovariance) {
  // A flat cell: eigenvalues 4, 1, 1e-6 -> the smallest becomes 4 / 100.
  const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized())
          .toRotationMatrix();
  const Eigen::Matrix3d c = rotation *
                            Eigen::Vector3d(4.0, 1.0, 1e-6).asDiagonal() *
                            rotation.transpose();
  NdtCell cell;
  ASSERT_TRUE(MakeNdtCell(10, Eigen::Vector3d::Zero(), c, Paper(), &cell));
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cell.covariance);
  EXPECT_NEAR(es.eigenvalues()(0), 0.04, 1e-12);
  EXPECT_NEAR(es.eigenvalues()(1), 1.0, 1e-12);
  EXPECT_NEAR(es.eigenvalues()(2), 4.0, 1e-12);
  EXPECT_TRUE((cell.covariance * cell.information)
                  .isApprox(Eigen::Matrix3d::Identity(), 1e-10));
}

TEST(NdtCell, RejectsShapelessCovariance) {
  NdtCell cell;
  EXPECT_FALSE(MakeNdtCell(
      5, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Zero(), Paper(), &cell));
  Eigen::Matrix3d bad = Eigen::Matrix3d::Identity();
  bad(0, 0) = std::nan("");
  EXPECT_FALSE(MakeNdtCell(5, Eigen::Vector3d::Zero(), bad, Paper(), &cell));
  EXPECT_EQ(cell.count, 0);  // Untouched.
}

}  // namespace
}  // namespace mlndt
