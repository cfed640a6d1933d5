#include "mlndt/cost/mlndt_point_cost_analytic.h"

#include <memory>

#include "mlndt/cost/transform_derivatives.h"

namespace mlndt {
namespace {

// The derivatives at `xi`, recomputed only when xi changes (per thread:
// Ceres' evaluator threads each keep their own).
const TransformDerivatives& DerivativesAt(const double* xi) {
  thread_local Vector6d cached_xi = Vector6d::Constant(0.0);
  thread_local std::unique_ptr<TransformDerivatives> cached;
  const Eigen::Map<const Vector6d> pose(xi);
  if (cached == nullptr || pose != cached_xi) {
    cached_xi = pose;
    cached = std::make_unique<TransformDerivatives>(cached_xi);
  }
  return *cached;
}

}  // namespace

bool MlNdtPointCostAnalytic::Evaluate(double const* const* parameters,
                                      double* residuals,
                                      double** jacobians) const {
  const TransformDerivatives& d = DerivativesAt(parameters[0]);
  const Eigen::Vector3d x = d.Transform(input_point_);
  const NdtCell* cell = MatchCell(layer_.layer(), x, policy_);
  Eigen::Map<Eigen::Vector3d> r(residuals);
  using Jacobian = Eigen::Matrix<double, 3, 6, Eigen::RowMajor>;
  const bool with_jacobian = jacobians != nullptr && jacobians[0] != nullptr;
  if (cell == nullptr) {
    r.setZero();
    if (with_jacobian) Eigen::Map<Jacobian>(jacobians[0]).setZero();
    return true;
  }
  r = cell->whitening * (x - cell->mean);
  if (with_jacobian) {
    Eigen::Map<Jacobian> j(jacobians[0]);
    j = cell->whitening * d.Jacobian(input_point_);
  }
  return true;
}

}  // namespace mlndt
