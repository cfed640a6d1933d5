#pragma once

// Localizability per direction of the pose: how many of the matched points
// constrain each direction through their surface's normal, as a share of
// those points (dimensionless; X-ICP, Tuna et al. 2023, and the degeneracy
// factor of Zhang, Kaess and Singh 2016, on point-to-plane information).
//
// A point x = R p + t matched to a planar cell (one thin direction,
// ThinCellDirections in quality_check.h) with unit normal n constrains the
// pose through the point-to-plane row J = [n; (R p) x n / L]: the residual
// n . (x - mu) changes by J . delta for a pose change delta (translation
// [m], rotation vector scaled to metres at the lever L, the points' RMS
// range). Each row is normalised, u = J / |J|, so that every point carries
// one unit of information whatever its lever. The directions are the
// eigenvectors v_k of A = sum_i u_i u_i^T, and point i constrains v_k when
// |u_i . v_k| >= constraining_cosine. The share of the points that do
// depends neither on the density (a corridor's axis has none at any count)
// nor on the NDT Hessian, whose in-plane terms come from each cell's
// extent (the covariance regularisation and the grid), not from a surface.

#include <vector>

#include "mlndt/common/types.h"
#include "mlndt/cost/point_matches.h"

namespace mlndt {

// The localizability of a pose at a solution (LocalizabilityOf).
struct Localizability {
  // Columns: unit directions of the pose vector (translation [m]; rotation
  // vector times L), the eigenvectors of A, weakest eigenvalue first.
  Matrix6d directions = Matrix6d::Zero();
  // Per direction: the share of the planar points that constrain it
  // (|u . v_k| >= the cosine), in [0, 1].
  Vector6d share = Vector6d::Zero();
  // Per direction: eigenvalue of A over the planar points, the mean
  // information a point gives it (in [0, 1], the six sum to 1).
  Vector6d information = Vector6d::Zero();
  // Matched points on planar cells: the rows counted.
  int planar_points = 0;
};

// Points whose normalised row has at least this cosine with a direction
// constrain it (X-ICP's contribution threshold; cos 60 deg).
constexpr double kConstrainingCosine = 0.5;

// The localizability of the points `input_points` moved by `rotation` onto
// their matches: the inliers (Mahalanobis distance below `gate`) on planar
// cells; rotations scaled by `rms_range_m` (> 0). Empty (planar_points 0)
// when no inlier lies on a planar cell.
Localizability LocalizabilityOf(
    const std::vector<Eigen::Vector3d>& input_points,
    const std::vector<PointMatch>& matches,
    const Matrix3d& rotation,
    double rms_range_m,
    double gate,
    double constraining_cosine = kConstrainingCosine);

}  // namespace mlndt
