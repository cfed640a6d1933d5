#pragma once

// Localizability of the translation, per direction: how many of the matched
// points constrain each direction through their surface's normal, as a
// share of those points (dimensionless; X-ICP, Tuna et al. 2023, on
// point-to-plane information, and the degeneracy factor of Zhang, Kaess and
// Singh 2016).
//
// A point x = R p + t matched to a planar cell (one thin direction,
// ThinCellDirections in registration/internal/cell_shape.h) with unit normal n
// constrains the translation through the point-to-plane residual n . (x - mu):
// a shift delta changes it by n . delta. With the rotation held (X-ICP
// decomposes the translation and rotation blocks apart), the directions are the
// eigenvectors v_k of A = sum_i n_i n_i^T, and point i constrains v_k when
// |n_i . v_k| >= constraining_cosine. The share of the points that do
// depends neither on the density (a corridor's axis has none at any count)
// nor on the NDT Hessian, whose in-plane terms come from each cell's extent
// (the covariance regularisation and the grid), not from a surface.

#include <vector>

#include "mlndt/common/types.h"
#include "mlndt/cost/point_matches.h"

namespace mlndt {

// The translation's localizability at a solution (LocalizabilityOf).
struct Localizability {
  // Columns: unit translation directions, the eigenvectors of A, weakest
  // eigenvalue first.
  Matrix3d directions = Matrix3d::Zero();
  // Per direction: the share of the planar inliers that constrain it
  // (|n . v_k| >= the cosine), in [0, 1].
  Eigen::Vector3d share = Eigen::Vector3d::Zero();
  // Per direction: the eigenvalue of A over the planar inliers, the mean
  // information a point gives it (in [0, 1]; the three sum to 1).
  Eigen::Vector3d information = Eigen::Vector3d::Zero();
  // Inliers on planar cells: the normals counted.
  int planar_points = 0;
};

// Normals at least this cosine from a direction constrain it (X-ICP's
// contribution threshold; cos 60 deg: a surface tilted less than 60 deg
// from facing the direction).
constexpr double kConstrainingCosine = 0.5;

// The localizability of `matches` (of the input points, at the solution):
// the inliers (Mahalanobis distance below `gate`) on planar cells. Empty
// (planar_points 0) when no inlier lies on a planar cell.
Localizability LocalizabilityOf(
    const std::vector<PointMatch>& matches,
    double gate,
    double constraining_cosine = kConstrainingCosine);

}  // namespace mlndt
