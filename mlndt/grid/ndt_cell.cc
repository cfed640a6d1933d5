#include "mlndt/grid/ndt_cell.h"

#include <Eigen/Eigenvalues>
#include <algorithm>

#include "mlndt/common/option_table.h"

namespace mlndt {

const OptionTable& CellRegularizationTable() {
  using S = CellRegularization;
  static const OptionTable table =
      OptionTableBuilder<S>("CellRegularization")
          .Double("min_eigenvalue_ratio",
                  &S::min_eigenvalue_ratio,
                  "",
                  Closed(1e-9, 1.0),
                  "Cell eigenvalues are floored at this fraction of the "
                  "largest (Section 4.1: 0.01).")
          .Double("min_eigenvalue_m2",
                  &S::min_eigenvalue_m2,
                  "m^2",
                  Closed(0.0, 1e6),
                  "Absolute floor on every cell covariance eigenvalue.")
          .Build();
  return table;
}

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
