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
// What a cell's points cannot resolve is not scored (lab/records/tilt.md). A
// spinning LiDAR cuts a surface in rings: the points of a cell lie on the
// few rings that cross it, so its covariance across the rings, within the
// surface, is the ring pattern's, not the surface's, and it moves with the
// sensor. Scored, it pulls the input's rings onto the reference's (a
// VLP-16's tilt between two scans came out 6-10 % short). So, when set, on
// the regularised eigenvalues:
//  - a cell whose points lie along a line (l2 < line_ratio * l3: one ring,
//    an edge) gives no distribution: the surface through it is not seen;
//  - a planar cell (l1 < plane_ratio * l2) constrains its normal only: C^-1
//    and W use in-plane eigenvalues of in_plane_variance_scale * l3 (the
//    in-plane residual weighs ~1 % of what it did; point-to-plane).
// `covariance` stays the regularised distribution (what a map file stores),
// so rebuilding a cell from it gives the same cell.
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
  int32_t count = 0;  // N, points in the cell.
  // Scored along its normal only (CellRegularization::plane_ratio):
  // `information` and `whitening` are not those of `covariance`.
  bool normal_only = false;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();        // mu, Eq. (2) [m].
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  // Regularised C [m^2].
  // C^-1 [1/m^2]; for a planar cell, of C with its in-plane eigenvalues
  // raised (CellRegularization::plane_ratio).
  Eigen::Matrix3d information = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d whitening =
      Eigen::Matrix3d::Zero();  // W, W^T W = C^-1 [1/m].
};

// How a cell covariance is regularised (eigenvalues l1 <= l2 <= l3).
struct CellRegularization {
  // Section 4.1: l1, l2 >= ratio * l3 (the paper: 1/100).
  double min_eigenvalue_ratio = 0.01;
  // Absolute floor on every eigenvalue [m^2] (sensor noise).
  double min_eigenvalue_m2 = 1e-3;
  // A cell with l2 < line_ratio * l3 holds points along a line and gives no
  // distribution. 0: off (the default and the paper; 0.1 removes most of the
  // tilt bias but the verdict's fit gate is not calibrated for it,
  // docs/defaults.md). In [0, 1).
  double line_ratio = 0.0;
  // A cell with l1 < plane_ratio * l2 is planar and scored along its normal
  // only (in-plane eigenvalues in_plane_variance_scale * l3 in C^-1 and W).
  // 0: off (the default and the paper; 0.1 with line_ratio). In [0, 1).
  double plane_ratio = 0.0;
  // In-plane eigenvalue of a planar cell's C^-1, in units of l3. In
  // [1, 1e6].
  double in_plane_variance_scale = 10.0;
};

// The library's floors with every cell scored with its whole covariance
// (line_ratio = plane_ratio = 0): Section 4.1, and Magnusson's NDT.
CellRegularization WholeCovarianceRegularization();

// CellRegularization's fields: name, unit, valid range and help
// (option_table.h).
const OptionTable& CellRegularizationTable();

// Fills `cell` from a mean and an unbiased covariance (Eq. 3), regularising
// the eigenvalues as described above. Returns false (and leaves `cell`
// untouched) when the covariance is not finite or has no positive eigenvalue,
// e.g. when all points coincide, or when the points lie along a line
// (line_ratio): such a cell carries no surface and is skipped.
bool MakeNdtCell(int32_t count,
                 const Eigen::Vector3d& mean,
                 const Eigen::Matrix3d& covariance,
                 const CellRegularization& regularization,
                 NdtCell* cell);

}  // namespace mlndt
