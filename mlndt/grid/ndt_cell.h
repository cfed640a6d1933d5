#pragma once

// One NDT cell: the normal distribution of the reference points in a box.
//
// ML-NDT Eq. (2) gives the mean and Eq. (3) the unbiased covariance of the
// N points in the cell. Section 4.1 (after Magnusson) regularises a nearly
// singular covariance: with eigenvalues l1 <= l2 <= l3, every eigenvalue below
// l3 / 100 is raised to l3 / 100 and C is rebuilt as V diag(l) V^T. The ratio
// is an option (`min_eigenvalue_ratio`, 0.01 in the paper). We add an
// absolute floor (`min_eigenvalue_m2`, sensor noise): without it a cell whose
// few points nearly coincide (one laser ring crossing a corner) gets an
// information matrix of 1e8 and more, and dominates the whole score.
//
// The score of a point x in the cell is e^T C^-1 e with e = x - mu (Eq. 10).
// We also keep the whitening matrix W = diag(l)^(-1/2) V^T, for which
// W^T W = C^-1, so that ||W e||^2 = e^T C^-1 e: W e is the residual a
// least-squares solver (Ceres, Levenberg-Marquardt) works with.

#include <Eigen/Core>
#include <cstdint>

namespace mlndt {

class OptionTable;

struct NdtCell {
  int32_t count = 0;                               // N, points in the cell.
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();  // mu, Eq. (2) [m].
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  // Regularised C [m^2].
  Eigen::Matrix3d information = Eigen::Matrix3d::Zero();  // C^-1 [1/m^2].
  Eigen::Matrix3d whitening =
      Eigen::Matrix3d::Zero();  // W, W^T W = C^-1 [1/m].
};

// How a cell covariance is regularised (eigenvalues l1 <= l2 <= l3).
struct CellRegularization {
  // Section 4.1: l1, l2 >= ratio * l3 (the paper: 1/100).
  double min_eigenvalue_ratio = 0.01;
  // Absolute floor on every eigenvalue [m^2] (sensor noise).
  double min_eigenvalue_m2 = 1e-3;
};

// CellRegularization's fields: name, unit, valid range and help
// (option_table.h).
const OptionTable& CellRegularizationTable();

// Fills `cell` from a mean and an unbiased covariance (Eq. 3), regularising
// the eigenvalues as described above. Returns false (and leaves `cell`
// untouched) when the covariance is not finite or has no positive eigenvalue,
// e.g. when all points coincide: such a cell carries no shape and is skipped.
bool MakeNdtCell(int32_t count,
                 const Eigen::Vector3d& mean,
                 const Eigen::Matrix3d& covariance,
                 const CellRegularization& regularization,
                 NdtCell* cell);

}  // namespace mlndt
