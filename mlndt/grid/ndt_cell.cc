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
          .Double("line_ratio",
                  &S::line_ratio,
                  "",
                  RightOpen(0.0, 1.0),
                  "A cell whose middle eigenvalue is below this fraction of "
                  "the largest (points along one ring or an edge) gives no "
                  "distribution; 0 = off.")
          .Double("plane_ratio",
                  &S::plane_ratio,
                  "",
                  RightOpen(0.0, 1.0),
                  "A cell whose smallest eigenvalue is below this fraction "
                  "of the middle one is scored along its normal only; 0 = "
                  "off.")
          .Double("in_plane_variance_scale",
                  &S::in_plane_variance_scale,
                  "",
                  Closed(1.0, 1e6),
                  "A planar cell's in-plane eigenvalues in C^-1, in units of "
                  "its largest eigenvalue.")
          .Build();
  return table;
}

CellRegularization WholeCovarianceRegularization() {
  CellRegularization regularization;
  regularization.line_ratio = 0.0;
  regularization.plane_ratio = 0.0;
  return regularization;
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
  // Decided on the regularised eigenvalues, so that a cell rebuilt from its
  // stored covariance (grid_io.h) is the same cell.
  if (eigenvalues(1) < regularization.line_ratio * largest) return false;
  Eigen::Vector3d scored = eigenvalues;  // The eigenvalues C^-1 and W use.
  cell->normal_only =
      eigenvalues(0) < regularization.plane_ratio * eigenvalues(1);
  if (cell->normal_only) {
    scored(1) = scored(2) = regularization.in_plane_variance_scale * largest;
  }
  const Eigen::Matrix3d& V = solver.eigenvectors();
  cell->count = count;
  cell->mean = mean;
  cell->covariance = V * eigenvalues.asDiagonal() * V.transpose();
  cell->information = V * scored.cwiseInverse().asDiagonal() * V.transpose();
  cell->whitening =
      scored.cwiseInverse().cwiseSqrt().asDiagonal() * V.transpose();
  return true;
}

}  // namespace mlndt
