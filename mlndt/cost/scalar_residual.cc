#include "mlndt/cost/scalar_residual.h"

#include "mlndt/cost/cell_match.h"
#include "mlndt/cost/robust_loss.h"
#include "mlndt/cost/transform_derivatives.h"

namespace mlndt {

ScalarResidualSystem EvaluateScalarResidualSystem(
    const NdtLayer& layer,
    const std::vector<Eigen::Vector3d>& input_points,
    const Vector6d& reference_from_input_xi,
    const ObjectiveOptions& objective) {
  const TransformDerivatives transform(reference_from_input_xi);
  ScalarResidualSystem system;
  for (const Eigen::Vector3d& p : input_points) {
    const Eigen::Vector3d x = transform.Transform(p);
    const NdtCell* cell = MatchCell(layer, x, objective.unmatched_policy);
    if (cell == nullptr) {
      ++system.unmatched;
      continue;
    }
    ++system.matched;
    const Eigen::Vector3d e = x - cell->mean;
    const Eigen::Vector3d information_e = cell->information * e;  // C^-1 e.
    double rho = 0.0, rho_prime = 1.0;
    EvaluateLoss(objective.loss,
                 objective.loss_scale,
                 e.dot(information_e),
                 &rho,
                 &rho_prime);
    system.score += rho;
    // J_k^T = rho' 2 [C^-1 e; A^T C^-1 e] (J = [I | A], Eq. 13 per point).
    Vector6d j;
    j.head<3>() = 2.0 * rho_prime * information_e;
    j.tail<3>() = 2.0 * rho_prime *
                  (transform.AngleJacobian(p).transpose() * information_e);
    system.jtj.noalias() += j * j.transpose();
    system.jtr += rho * j;
  }
  return system;
}

}  // namespace mlndt
