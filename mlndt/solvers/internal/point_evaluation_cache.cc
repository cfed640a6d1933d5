#include "mlndt/solvers/internal/point_evaluation_cache.h"

#include <glog/logging.h>

#include <cstring>

namespace mlndt {
namespace internal {

namespace {

bool SameXi(const double* a, const double* b) {
  return std::memcmp(a, b, 6 * sizeof(double)) == 0;
}

}  // namespace

PointEvaluationCache::PointEvaluationCache(
    std::vector<const ceres::CostFunction*> costs,
    const double* xi,
    int threads)
    : costs_(std::move(costs)),
      xi_(xi),
      workers_(threads),
      residuals_(3 * costs_.size()),
      jacobians_(18 * costs_.size()),
      ok_(costs_.size()) {
  CHECK(xi_ != nullptr);
}

void PointEvaluationCache::PrepareForEvaluation(bool evaluate_jacobians,
                                                bool new_evaluation_point) {
  // Ceres evaluates the residuals at a candidate and, when it accepts it,
  // the Jacobians at the same point: without the cache each block would then
  // be evaluated again, with Jacobians, so the slots are filled again too.
  if (new_evaluation_point || !filled_ ||
      filled_with_jacobians_ != evaluate_jacobians ||
      !SameXi(filled_xi_, xi_)) {
    Fill(evaluate_jacobians);
  }
}

// Every point writes its own slots only: nothing is summed here, so the
// number of slices cannot change a bit.
void PointEvaluationCache::Fill(bool with_jacobians) {
  std::memcpy(filled_xi_, xi_, sizeof(filled_xi_));
  const size_t n = costs_.size();
  const size_t slices = static_cast<size_t>(workers_.slices());
  workers_.Run([&](int slice) {
    const size_t s = static_cast<size_t>(slice);
    const double* parameters[1] = {filled_xi_};
    for (size_t i = n * s / slices; i < n * (s + 1) / slices; ++i) {
      double* jacobian = &jacobians_[18 * i];
      ok_[i] = costs_[i]->Evaluate(
          parameters, &residuals_[3 * i], with_jacobians ? &jacobian : nullptr);
    }
  });
  filled_ = true;
  filled_with_jacobians_ = with_jacobians;
}

bool PointEvaluationCache::Lookup(size_t i,
                                  const double* xi,
                                  double* residuals,
                                  double* jacobian,
                                  bool* ok) const {
  if (!filled_ || (jacobian != nullptr) != filled_with_jacobians_ ||
      !SameXi(xi, filled_xi_)) {
    return false;
  }
  std::memcpy(residuals, &residuals_[3 * i], 3 * sizeof(double));
  if (jacobian != nullptr) {
    std::memcpy(jacobian, &jacobians_[18 * i], 18 * sizeof(double));
  }
  *ok = ok_[i] != 0;
  return true;
}

bool CachedPointCost::Evaluate(double const* const* parameters,
                               double* residuals,
                               double** jacobians) const {
  // A Jacobian array without xi's entry: auto-diff still evaluates with
  // Jets, which the slots do not distinguish; the cost function answers.
  if (jacobians != nullptr && jacobians[0] == nullptr) {
    return cost_.Evaluate(parameters, residuals, jacobians);
  }
  double* jacobian = jacobians != nullptr ? jacobians[0] : nullptr;
  bool ok = false;
  if (cache_.Lookup(index_, parameters[0], residuals, jacobian, &ok)) {
    return ok;
  }
  return cost_.Evaluate(parameters, residuals, jacobians);
}

}  // namespace internal
}  // namespace mlndt
