#pragma once

// The sampled input points at one pose on one layer, each matched to its
// cell once (cell_match.h): what everything judged at a solution reads —
// the fit (fit_quality.h), the thin-direction information and the probe's
// inliers (registration/quality_check.h) — so that the verdict does not
// look every point up again per measure.

#include <vector>

#include "mlndt/common/types.h"
#include "mlndt/cost/cell_match.h"
#include "mlndt/grid/ndt_layer.h"

namespace mlndt {

struct PointMatch {
  Eigen::Vector3d x = Eigen::Vector3d::Zero();  // R p + t.
  const NdtCell* cell = nullptr;  // As the policy picks; nullptr: unmatched.
  // s = e^T C^-1 e with e = x - mean in that cell (Eq. 10), C the cell's
  // whole covariance (also for a cell the objective scores along its normal
  // only, NdtCell::normal_only); 0 if unmatched.
  double score = 0.0;
  bool own_cell = false;  // The cell x lies in is occupied (overlap).

  // Matched, at a Mahalanobis distance below `gate`.
  bool IsInlier(double gate) const {
    return cell != nullptr && score < gate * gate;
  }
};

// One transformed point x matched on `layer` with `policy`.
PointMatch MatchPoint(const NdtLayer& layer,
                      const Eigen::Vector3d& x,
                      UnmatchedPolicy policy);

// Every point of `input_points` moved by x = rotation p + translation and
// matched on `layer` with `policy`, in input order.
std::vector<PointMatch> MatchPoints(
    const NdtLayer& layer,
    const std::vector<Eigen::Vector3d>& input_points,
    const Matrix3d& rotation,
    const Eigen::Vector3d& translation,
    UnmatchedPolicy policy);

}  // namespace mlndt
