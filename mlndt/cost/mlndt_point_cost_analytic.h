#pragma once

// MlNdtPointCost (mlndt_point_cost.h) with hand-written Jacobians: the same
// residual r = W (R(xi) x + t - mu) on the 6-vector xi of Eq. (11), with
// dr/dxi = W dx'/dxi from TransformDerivatives (the derivatives of Eqs. 6-8
// the Newton and LM backends use). The rotation's derivatives depend on xi
// only: they are computed once per pose and thread and reused by every
// point evaluated at that pose. For the Ceres backend's
// analytic_jacobians option and mlndt_bench's --jacobians axis.

#include <ceres/sized_cost_function.h>

#include <Eigen/Core>

#include "mlndt/cost/cell_match.h"
#include "mlndt/cost/layer_binding.h"

namespace mlndt {

class MlNdtPointCostAnalytic : public ceres::SizedCostFunction<3, 6> {
 public:
  MlNdtPointCostAnalytic(LayerSource layer,
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
