#include "mlndt/cost/score.h"

#include <algorithm>

#include "mlndt/cost/internal/score_reduction.h"
#include "mlndt/cost/transform_derivatives.h"

namespace mlndt {
namespace {

void Accumulate(const NdtLayer& layer,
                const std::vector<Eigen::Vector3d>& points,
                size_t begin,
                size_t end,
                const TransformDerivatives& transform,
                const ObjectiveOptions& objective,
                HessianType hessian,
                ScoreEvaluation* sum) {
  LossSum loss(objective.loss, objective.loss_scale);
  for (size_t k = begin; k < end; ++k) {
    const Eigen::Vector3d& p = points[k];
    const Eigen::Vector3d x = transform.Transform(p);
    const NdtCell* cell = MatchCell(layer, x, objective.unmatched_policy);
    if (cell == nullptr) {
      ++sum->unmatched;
      continue;
    }
    ++sum->matched;
    const Eigen::Vector3d e = x - cell->mean;
    const Eigen::Vector3d information_e = cell->information * e;  // C^-1 e.
    const double rho_prime = loss.Add(e.dot(information_e));
    if (hessian == HessianType::NONE) continue;
    // J = [I | A] with A = d x' / d angles, so J^T C^-1 e = [C^-1 e; A^T C^-1
    // e] and J^T C^-1 J = [C^-1, C^-1 A; A^T C^-1, A^T C^-1 A].
    const double w = 2.0 * rho_prime;
    const Matrix3d a = transform.AngleJacobian(p);
    const Matrix3d information_a = cell->information * a;
    sum->gradient.head<3>() += w * information_e;
    sum->gradient.tail<3>().noalias() += w * (a.transpose() * information_e);
    sum->hessian.topLeftCorner<3, 3>() += w * cell->information;
    sum->hessian.topRightCorner<3, 3>() += w * information_a;
    sum->hessian.bottomRightCorner<3, 3>().noalias() +=
        w * (a.transpose() * information_a);
    if (hessian == HessianType::FULL) {
      sum->hessian += (2.0 * rho_prime) *
                      transform.WeightedSecondDerivative(p, information_e);
    }
  }
  sum->score += loss.Total();
}

}  // namespace

ScoreEvaluation EvaluateScore(const NdtLayer& layer,
                              const std::vector<Eigen::Vector3d>& input_points,
                              const Vector6d& reference_from_input_xi,
                              const ObjectiveOptions& objective,
                              HessianType hessian,
                              int num_threads) {
  const TransformDerivatives transform(reference_from_input_xi);
  return internal::ReduceScoreInSlices(
      input_points.size(),
      std::max(1, num_threads),
      [&](size_t begin, size_t end, ScoreEvaluation* partial) {
        Accumulate(layer,
                   input_points,
                   begin,
                   end,
                   transform,
                   objective,
                   hessian,
                   partial);
        // The lower-left block by symmetry.
        partial->hessian.bottomLeftCorner<3, 3>() =
            partial->hessian.topRightCorner<3, 3>().transpose();
      });
}

}  // namespace mlndt
