#pragma once

// The paper's literal Levenberg-Marquardt system (Section 4.2, Eqs. 18-20):
// the per-point score itself is the residual,
//
//   r_k = rho(s_k),   s_k = e_k^T C_k^-1 e_k,
//   J_k = d r_k / d xi = rho'(s_k) 2 e_k^T C_k^-1 [I | A_k]     (1 x 6)
//
// and the update solves (J^T J + lambda I) delta = -J^T r, with
// J^T J = sum_k J_k^T J_k and J^T r = sum_k r_k J_k^T. These normal
// equations are those of (1/2) sum_k r_k^2, not of the score sum_k r_k that
// Newton, our LM (whitened 3-vector residuals W_k e_k) and Ceres minimise:
// the step weighs each point by its own score, so far points pull harder.
// The score, and whether a step lowers it, is still sum_k rho(s_k).

#include <vector>

#include "mlndt/common/types.h"
#include "mlndt/cost/objective_options.h"
#include "mlndt/grid/ndt_layer.h"

namespace mlndt {

struct ScalarResidualSystem {
  double score = 0.0;  // sum_k rho(s_k) (as EvaluateScore).
  size_t matched = 0;
  size_t unmatched = 0;
  Matrix6d jtj = Matrix6d::Zero();  // sum_k J_k^T J_k.
  Vector6d jtr = Vector6d::Zero();  // sum_k r_k J_k^T.
};

// The system of `input_points` moved by xi onto `layer` (single-threaded).
ScalarResidualSystem EvaluateScalarResidualSystem(
    const NdtLayer& layer,
    const std::vector<Eigen::Vector3d>& input_points,
    const Vector6d& reference_from_input_xi,
    const ObjectiveOptions& objective);

}  // namespace mlndt
