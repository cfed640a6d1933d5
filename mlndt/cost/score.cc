#include "mlndt/cost/score.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "mlndt/cost/internal/score_reduction.h"
#include "mlndt/cost/transform_derivatives.h"

namespace mlndt {
namespace {

// The Cauchy loss summed over a slice as b log(prod_k (1 + s_k / b)): one
// log per slice instead of a log1p per point, a large share of the
// hand-written backends' profile (docs/performance.md). The product is kept as
// mantissa and binary exponent, renormalised once it reaches 2^500, so it
// cannot overflow while a factor is below 2^523 (a matched point's s is
// bounded by its cell's neighbourhood and the covariance floor: far less).
class CauchySum {
 public:
  void Add(double u) {  // u = s / b >= 0.
    product_ *= 1.0 + u;
    if (product_ >= 0x1p500) {
      int exponent = 0;
      product_ = std::frexp(product_, &exponent);
      exponent_ += exponent;
    }
  }
  // sum_k log(1 + u_k).
  double Log() const { return std::log(product_) + exponent_ * M_LN2; }

 private:
  double product_ = 1.0;
  int64_t exponent_ = 0;
};

void Accumulate(const NdtLayer& layer,
                const std::vector<Eigen::Vector3d>& points,
                size_t begin,
                size_t end,
                const TransformDerivatives& transform,
                const ObjectiveOptions& objective,
                HessianType hessian,
                ScoreEvaluation* sum) {
  const bool cauchy = objective.loss == LossType::CAUCHY;
  const double b = objective.loss_scale * objective.loss_scale;
  CauchySum cauchy_sum;
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
    const double s = e.dot(information_e);
    double rho = 0.0, rho_prime = 1.0;
    if (cauchy) {  // As EvaluateLoss, rho summed by cauchy_sum.
      cauchy_sum.Add(s / b);
      rho_prime = 1.0 / (1.0 + s / b);
    } else {
      EvaluateLoss(objective.loss, objective.loss_scale, s, &rho, &rho_prime);
      sum->score += rho;
    }
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
  if (cauchy) sum->score += b * cauchy_sum.Log();
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
