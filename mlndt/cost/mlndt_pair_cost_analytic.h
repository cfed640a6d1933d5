#pragma once

// MlNdtPairCost (mlndt_pair_cost.h) with hand-written Jacobians: the same
// residual r = W (R_i^T (R_j p + t_j - t_i) - mu) on the same blocks
// (quaternion x, y, z, w and translation of world_from_scan_i and _j), for
// back ends where the 14-wide auto-diff Jets dominate the solve
// (docs/embedding.md measures both). With v = R_j p + t_j - t_i:
//
//   dr/dt_j =  W R_i^T          dr/dq_j = W R_i^T dRot(q_j, p)/dq_j
//   dr/dt_i = -W R_i^T          dr/dq_i = W dRot(conj(q_i), v)/dq_i
//
// where Rot(q, x) = x + 2w (u x x) + 2 u x (u x x), q = (u, w), is Eigen's
// quaternion-vector product; its derivative in the 4 ambient coordinates is
// d/du = 2 ((u.x) I + u x^T - 2 x u^T) - 2w [x]_x and d/dw = 2 u x x, so the
// Jacobians equal the auto-diff ones entry by entry (tests compare them).
// The cell lookup and the unmatched-point rule are WhitenedCellResidual's;
// an unmatched point under ZERO_RESIDUAL has zero residual and Jacobians.

#include <ceres/sized_cost_function.h>

#include <Eigen/Core>

#include "mlndt/cost/cell_match.h"
#include "mlndt/cost/layer_binding.h"

namespace mlndt {

class MlNdtPairCostAnalytic : public ceres::SizedCostFunction<3, 4, 3, 4, 3> {
 public:
  // As MlNdtPairCost: a layer of scan i's map (or a binding to one) and a
  // point of scan j in scan j's frame [m].
  MlNdtPairCostAnalytic(LayerSource layer,
                        const Eigen::Vector3d& input_point,
                        UnmatchedPolicy policy)
      : layer_(layer), input_point_(input_point), policy_(policy) {}

  bool Evaluate(double const* const* parameters,
                double* residuals,
                double** jacobians) const override;

 private:
  const LayerSource layer_;
  const Eigen::Vector3d input_point_;
  const UnmatchedPolicy policy_;
};

}  // namespace mlndt
