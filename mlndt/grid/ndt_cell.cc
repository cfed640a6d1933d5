#include "mlndt/grid/ndt_cell.h"

#include <Eigen/Eigenvalues>
#include <algorithm>

namespace mlndt {

bool MakeNdtCell(int32_t count,
                 const Eigen::Vector3d& mean,
                 const Eigen::Matrix3d& covariance,
                 const CellRegularization& regularization,
                 NdtCell* cell) {
  if (!mean.allFinite() || !covariance.allFinite()) return false;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  if (solver.info() != Eigen::Success) return false;
  // Eigenvalues come sorted in increasing order.
  Eigen::Vector3d eigenvalues = solver.eigenvalues();
  const double largest = eigenvalues(2);
  if (!(largest > 0.0)) return false;
  // Section 4.1: l_j = max(l_j, l3 / 100), and the absolute floor.
  const double floor_value =
      std::max(largest * regularization.min_eigenvalue_ratio,
               regularization.min_eigenvalue_m2);
  eigenvalues = eigenvalues.cwiseMax(floor_value);
  if (!(eigenvalues(0) > 0.0)) return false;
  const Eigen::Matrix3d& V = solver.eigenvectors();
  cell->count = count;
  cell->mean = mean;
  cell->covariance = V * eigenvalues.asDiagonal() * V.transpose();
  cell->information =
      V * eigenvalues.cwiseInverse().asDiagonal() * V.transpose();
  cell->whitening =
      eigenvalues.cwiseInverse().cwiseSqrt().asDiagonal() * V.transpose();
  return true;
}

}  // namespace mlndt
