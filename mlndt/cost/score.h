#pragma once

// The ML-NDT objective over a set of input points on one layer, evaluated
// directly (no ceres::Problem): score = sum_k rho(e_k^T C_k^-1 e_k) (Eq. 10,
// with an optional robust loss), its gradient and the Gauss-Newton part of
// its Hessian, 2 sum J^T W^T W J (Eq. 14 without the second-order term).
// Used for reports (final score, Hessian, covariance, matched counts).

#include <vector>

#include "mlndt/common/types.h"
#include "mlndt/cost/cell_match.h"
#include "mlndt/cost/robust_loss.h"
#include "mlndt/grid/ndt_layer.h"

namespace mlndt {

struct ScoreEvaluation {
  double score = 0.0;                         // sum_k rho(s_k).
  size_t matched = 0;                         // Points scored against a cell.
  size_t unmatched = 0;                       // Points contributing nothing.
  Vector6d gradient = Vector6d::Zero();       // d score / d xi.
  Matrix6d hessian = Matrix6d::Zero();        // Gauss-Newton Hessian of score.
};

ScoreEvaluation EvaluateScore(const NdtLayer& layer,
                              const std::vector<Eigen::Vector3d>& input_points,
                              const Vector6d& reference_from_input_xi,
                              UnmatchedPolicy policy,
                              LossType loss,
                              double loss_scale);

}  // namespace mlndt
