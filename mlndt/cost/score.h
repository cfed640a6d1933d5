#pragma once

// The ML-NDT objective over a set of input points on one layer, with its
// analytic derivatives (no ceres::Problem, no auto-diff):
//
//   score = sum_k rho(s_k),   s_k = e_k^T C_k^-1 e_k            (Eq. 10, 12)
//   g     = sum_k rho'(s_k) 2 J_k^T C_k^-1 e_k                   (Eq. 13)
//   H     = sum_k rho'(s_k) 2 (J_k^T C_k^-1 J_k
//                              + sum_i (C_k^-1 e_k)_i d2x'_i/dxi2) (Eq. 14)
//
// with J_k = d x'_k / d xi (transform_derivatives.h). HessianType::FULL
// keeps the second-order term of Eq. (14) (Newton, Section 4.1);
// GAUSS_NEWTON drops it (LM, reports). With a robust loss the rho'' term is
// left out of H (iteratively reweighted least squares), so H stays positive
// semi-definite in the Gauss-Newton case. rho = identity for LossType::NONE.
//
// The hand-written backends and the reports (final score, Hessian,
// covariance, matched counts) use it; the Ceres backend minimises the same
// sum through auto-diff residuals W e_k (||W e||^2 = s).

#include <vector>

#include "mlndt/common/types.h"
#include "mlndt/cost/objective_options.h"
#include "mlndt/grid/ndt_layer.h"

namespace mlndt {

enum class HessianType {
  NONE,          // Score and counts only (line searches, reports).
  GAUSS_NEWTON,  // 2 sum J^T C^-1 J.
  FULL,          // Plus the second-order term of Eq. (14).
};

struct ScoreEvaluation {
  double score = 0.0;                    // sum_k rho(s_k).
  size_t matched = 0;                    // Points scored against a cell.
  size_t unmatched = 0;                  // Points contributing nothing.
  Vector6d gradient = Vector6d::Zero();  // d score / d xi.
  Matrix6d hessian = Matrix6d::Zero();   // As the HessianType asked.
};

// The score of `input_points` moved by xi onto `layer`, with the requested
// derivatives. `num_threads` OpenMP threads split the points (>= 1); the
// partial sums are reduced in a fixed order, so a given thread count always
// gives the same bits.
ScoreEvaluation EvaluateScore(const NdtLayer& layer,
                              const std::vector<Eigen::Vector3d>& input_points,
                              const Vector6d& reference_from_input_xi,
                              const ObjectiveOptions& objective,
                              HessianType hessian = HessianType::GAUSS_NEWTON,
                              int num_threads = 1);

}  // namespace mlndt
