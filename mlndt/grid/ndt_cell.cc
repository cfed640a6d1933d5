#include "mlndt/grid/ndt_cell.h"

#include <Eigen/Eigenvalues>

namespace mlndt {

bool MakeNdtCell(int32_t count,
                 const Eigen::Vector3d& mean,
                 const Eigen::Matrix3d& covariance,
                 double min_eigenvalue_ratio,
                 NdtCell* cell) {
  if (!mean.allFinite() || !covariance.allFinite()) return false;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  if (solver.info() != Eigen::Success) return false;
  // Eigenvalues come sorted in increasing order.
  Eigen::Vector3d eigenvalues = solver.eigenvalues();
  const double largest = eigenvalues(2);
  if (!(largest > 0.0)) return false;
  // Section 4.1: l_j = max(l_j, l3 / 100).
  const double floor_value = largest * min_eigenvalue_ratio;
  eigenvalues = eigenvalues.cwiseMax(floor_value);
  if (!(eigenvalues(0) > 0.0)) return false;
  const Eigen::Matrix3d& V = solver.eigenvectors();
  cell->count = count;
  cell->mean = mean;
  cell->covariance = V * eigenvalues.asDiagonal() * V.transpose();
  cell->information = V * eigenvalues.cwiseInverse().asDiagonal() * V.transpose();
  cell->whitening = eigenvalues.cwiseInverse().cwiseSqrt().asDiagonal() * V.transpose();
  return true;
}

}  // namespace mlndt
