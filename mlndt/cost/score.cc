#include "mlndt/cost/score.h"

#include <ceres/jet.h>

#include "mlndt/common/pose.h"

namespace mlndt {

ScoreEvaluation EvaluateScore(const NdtLayer& layer,
                              const std::vector<Eigen::Vector3d>& input_points,
                              const Vector6d& reference_from_input_xi,
                              UnmatchedPolicy policy,
                              LossType loss,
                              double loss_scale) {
  using Jet = ceres::Jet<double, 6>;
  Jet xi[6];
  for (int i = 0; i < 6; ++i) xi[i] = Jet(reference_from_input_xi(i), i);
  ScoreEvaluation result;
  for (const Eigen::Vector3d& p : input_points) {
    const Eigen::Matrix<Jet, 3, 1> x = TransformPoint(xi, p);
    const Eigen::Vector3d value(x(0).a, x(1).a, x(2).a);
    const NdtCell* cell = MatchCell(layer, value, policy);
    if (cell == nullptr) {
      ++result.unmatched;
      continue;
    }
    ++result.matched;
    Eigen::Matrix<double, 3, 6> dx;  // d x' / d xi.
    for (int r = 0; r < 3; ++r) dx.row(r) = x(r).v.transpose();
    const Eigen::Vector3d residual = cell->whitening * (value - cell->mean);
    const Eigen::Matrix<double, 3, 6> jacobian = cell->whitening * dx;
    double rho = 0.0, rho_prime = 1.0;
    EvaluateLoss(loss, loss_scale, residual.squaredNorm(), &rho, &rho_prime);
    result.score += rho;
    result.gradient += 2.0 * rho_prime * jacobian.transpose() * residual;
    result.hessian += 2.0 * rho_prime * jacobian.transpose() * jacobian;
  }
  return result;
}

}  // namespace mlndt
