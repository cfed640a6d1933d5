#include "mlndt/grid/ndt_cell.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

namespace mlndt {
namespace {

// Section 4.1 exactly: the relative floor only.
CellRegularization Paper() {
  CellRegularization r = WholeCovarianceRegularization();
  r.min_eigenvalue_m2 = 0.0;
  return r;
}

// The cell rules on (line_ratio, plane_ratio 0.1; the library's default is
// off).
CellRegularization Rules() {
  CellRegularization r;
  r.line_ratio = 0.1;
  r.plane_ratio = 0.1;
  return r;
}

// A covariance with eigenvalues `l` (ascending) along a rotated basis.
Eigen::Matrix3d Rotated(const Eigen::Vector3d& l, Eigen::Matrix3d* basis) {
  *basis = Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized())
               .toRotationMatrix();
  return *basis * l.asDiagonal() * basis->transpose();
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

TEST(NdtCell, LineCellGivesNoDistribution) {
  // One ring across a 1 m cell: 1/12 m^2 along it, 2 cm and 3 cm across.
  Eigen::Matrix3d basis;
  const Eigen::Matrix3d line =
      Rotated(Eigen::Vector3d(4e-4, 9e-4, 1.0 / 12.0), &basis);
  NdtCell cell;
  EXPECT_FALSE(MakeNdtCell(20, Eigen::Vector3d::Zero(), line, Rules(), &cell));
  EXPECT_EQ(cell.count, 0);
  // The paper's cell keeps it.
  EXPECT_TRUE(MakeNdtCell(20,
                          Eigen::Vector3d::Zero(),
                          line,
                          WholeCovarianceRegularization(),
                          &cell));
}

TEST(NdtCell, PlanarCellIsScoredAlongItsNormal) {
  // A wall patch: 1/12 m^2 both ways in the plane, 2 cm thick.
  Eigen::Matrix3d basis;
  const Eigen::Matrix3d plane =
      Rotated(Eigen::Vector3d(4e-4, 0.07, 1.0 / 12.0), &basis);
  const CellRegularization regularization = Rules();
  NdtCell cell;
  ASSERT_TRUE(
      MakeNdtCell(20, Eigen::Vector3d::Zero(), plane, regularization, &cell));
  EXPECT_TRUE(cell.normal_only);
  const Eigen::Vector3d normal = basis.col(0);
  const Eigen::Vector3d in_plane = basis.col(1);
  // Along the normal: the floored thickness, 1e-3 m^2.
  EXPECT_NEAR(normal.dot(cell.information * normal), 1e3, 1e-6);
  // In the plane: in_plane_variance_scale times the largest eigenvalue.
  EXPECT_NEAR(in_plane.dot(cell.information * in_plane),
              1.0 / (regularization.in_plane_variance_scale / 12.0),
              1e-9);
  EXPECT_TRUE((cell.whitening.transpose() * cell.whitening)
                  .isApprox(cell.information, 1e-12));
  // The covariance stays the regularised distribution, and a cell rebuilt
  // from it (a map file) is the same cell.
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cell.covariance);
  EXPECT_NEAR(es.eigenvalues()(0), 1e-3, 1e-12);
  EXPECT_NEAR(es.eigenvalues()(1), 0.07, 1e-12);
  NdtCell again;
  ASSERT_TRUE(MakeNdtCell(
      20, Eigen::Vector3d::Zero(), cell.covariance, regularization, &again));
  EXPECT_TRUE(again.information.isApprox(cell.information, 1e-12));
  // Off, the in-plane direction keeps its own eigenvalue.
  ASSERT_TRUE(MakeNdtCell(20,
                          Eigen::Vector3d::Zero(),
                          plane,
                          WholeCovarianceRegularization(),
                          &cell));
  EXPECT_NEAR(in_plane.dot(cell.information * in_plane), 1.0 / 0.07, 1e-9);
  EXPECT_FALSE(cell.normal_only);
}

}  // namespace
}  // namespace mlndt
