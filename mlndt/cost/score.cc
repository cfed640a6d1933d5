#include "mlndt/cost/score.h"

#include <algorithm>

#include <omp.h>

#include "mlndt/cost/transform_derivatives.h"

namespace mlndt {
namespace {

void Accumulate(const NdtLayer& layer,
                const std::vector<Eigen::Vector3d>& points,
                size_t begin,
                size_t end,
                const TransformDerivatives& transform,
                const ScoreOptions& options,
                ScoreEvaluation* sum) {
  for (size_t k = begin; k < end; ++k) {
    const Eigen::Vector3d& p = points[k];
    const Eigen::Vector3d x = transform.Transform(p);
    const NdtCell* cell = MatchCell(layer, x, options.unmatched_policy);
    if (cell == nullptr) {
      ++sum->unmatched;
      continue;
    }
    ++sum->matched;
    const Eigen::Vector3d e = x - cell->mean;
    const Eigen::Vector3d information_e = cell->information * e;  // C^-1 e.
    double rho = 0.0, rho_prime = 1.0;
    EvaluateLoss(options.loss, options.loss_scale, e.dot(information_e), &rho, &rho_prime);
    sum->score += rho;
    if (options.hessian == HessianType::NONE) continue;
    const Eigen::Matrix<double, 3, 6> jacobian = transform.Jacobian(p);
    sum->gradient.noalias() += (2.0 * rho_prime) * (jacobian.transpose() * information_e);
    sum->hessian.noalias() +=
        (2.0 * rho_prime) * (jacobian.transpose() * cell->information * jacobian);
    if (options.hessian == HessianType::FULL) {
      sum->hessian += (2.0 * rho_prime) * transform.WeightedSecondDerivative(p, information_e);
    }
  }
}

}  // namespace

ScoreEvaluation EvaluateScore(const NdtLayer& layer,
                              const std::vector<Eigen::Vector3d>& input_points,
                              const Vector6d& reference_from_input_xi,
                              const ScoreOptions& options) {
  const TransformDerivatives transform(reference_from_input_xi);
  const int threads = std::max(1, options.num_threads);
  std::vector<ScoreEvaluation> partial(static_cast<size_t>(threads));
  const size_t n = input_points.size();
#pragma omp parallel for num_threads(threads) schedule(static, 1)
  for (int t = 0; t < threads; ++t) {
    const size_t begin = n * static_cast<size_t>(t) / static_cast<size_t>(threads);
    const size_t end = n * static_cast<size_t>(t + 1) / static_cast<size_t>(threads);
    Accumulate(layer, input_points, begin, end, transform, options,
               &partial[static_cast<size_t>(t)]);
  }
  ScoreEvaluation total = partial[0];
  for (size_t t = 1; t < partial.size(); ++t) {
    total.score += partial[t].score;
    total.matched += partial[t].matched;
    total.unmatched += partial[t].unmatched;
    total.gradient += partial[t].gradient;
    total.hessian += partial[t].hessian;
  }
  return total;
}

ScoreEvaluation EvaluateScore(const NdtLayer& layer,
                              const std::vector<Eigen::Vector3d>& input_points,
                              const Vector6d& reference_from_input_xi,
                              UnmatchedPolicy policy,
                              LossType loss,
                              double loss_scale) {
  ScoreOptions options;
  options.unmatched_policy = policy;
  options.loss = loss;
  options.loss_scale = loss_scale;
  return EvaluateScore(layer, input_points, reference_from_input_xi, options);
}

}  // namespace mlndt
