#pragma once

// One NDT cell: the normal distribution of the reference points in a box.
//
// ML-NDT Eq. (2) gives the mean and Eq. (3) the unbiased covariance of the
// N points in the cell. Section 4.1 (after Magnusson) regularises a nearly
// singular covariance: with eigenvalues l1 <= l2 <= l3, every eigenvalue below
// l3 / 100 is raised to l3 / 100 and C is rebuilt as V diag(l) V^T. The ratio
// is an option (`min_eigenvalue_ratio`, 0.01 in the paper).
//
// The score of a point x in the cell is e^T C^-1 e with e = x - mu (Eq. 10).
// We also keep the whitening matrix W = diag(l)^(-1/2) V^T, for which
// W^T W = C^-1, so that ||W e||^2 = e^T C^-1 e: W e is the residual a
// least-squares solver (Ceres, Levenberg-Marquardt) works with.

#include <cstdint>

#include <Eigen/Core>

namespace mlndt {

struct NdtCell {
  int32_t count = 0;                                       // N, points in the cell.
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();          // mu, Eq. (2) [m].
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();    // Regularised C [m^2].
  Eigen::Matrix3d information = Eigen::Matrix3d::Zero();   // C^-1 [1/m^2].
  Eigen::Matrix3d whitening = Eigen::Matrix3d::Zero();     // W, W^T W = C^-1 [1/m].
};

// Fills `cell` from a mean and an unbiased covariance (Eq. 3), regularising
// the eigenvalues as described above. Returns false (and leaves `cell`
// untouched) when the covariance is not finite or has no positive eigenvalue,
// e.g. when all points coincide: such a cell carries no shape and is skipped.
bool MakeNdtCell(int32_t count,
                 const Eigen::Vector3d& mean,
                 const Eigen::Matrix3d& covariance,
                 double min_eigenvalue_ratio,
                 NdtCell* cell);

}  // namespace mlndt
