#pragma once

// Parallel evaluation of the Ceres backend's residual blocks (one per
// sampled point, each 3 residuals of the 6-vector xi) that keeps the bits of
// a one-thread evaluation.
//
// Ceres' own evaluator threads sum the cost and gradient in per-thread
// partial sums whose split depends on the scheduler, so its results change
// with the thread count. Instead, Ceres runs on one thread and this
// ceres::EvaluationCallback evaluates every block's cost function before
// Ceres asks for it: PrepareForEvaluation runs the points' cost functions on
// `threads` threads (slice_workers.h) at the new xi and keeps each point's
// residuals (and Jacobian) in its own slot. Ceres' one thread then calls
// CachedPointCost, which copies the slot, and sums the cost in block order,
// as it does without the cache. The blocks, losses, order and sums are the
// same, and each point's numbers come from the same cost function called
// with the same arguments, so the solve is bit-identical to one without the
// cache, for any number of threads.
//
// A slot is used only when the block asks at the xi (same bits) and with the
// Jacobian request the slot was filled with; otherwise CachedPointCost calls
// the cost function itself, so a request the cache did not foresee is still
// answered exactly.

#include <ceres/cost_function.h>
#include <ceres/evaluation_callback.h>
#include <ceres/sized_cost_function.h>

#include <cstddef>
#include <vector>

#include "mlndt/solvers/internal/slice_workers.h"

namespace mlndt {
namespace internal {

class PointEvaluationCache : public ceres::EvaluationCallback {
 public:
  // `costs`: the blocks' cost functions (3 residuals, one 6-parameter
  // block), in block order; not owned, they must outlive the cache. `xi`:
  // the problem's parameter block (user memory, which Ceres updates before
  // every PrepareForEvaluation). `threads` >= 1.
  PointEvaluationCache(std::vector<const ceres::CostFunction*> costs,
                       const double* xi,
                       int threads);

  void PrepareForEvaluation(bool evaluate_jacobians,
                            bool new_evaluation_point) override;

  // Point i's residuals (3) and, when `jacobian` is not null, its row-major
  // 3x6 Jacobian at `xi`, with the cost function's return value in *ok;
  // false when the slot was not filled at `xi` with this Jacobian request.
  bool Lookup(size_t i,
              const double* xi,
              double* residuals,
              double* jacobian,
              bool* ok) const;

 private:
  void Fill(bool with_jacobians);

  const std::vector<const ceres::CostFunction*> costs_;
  const double* const xi_;
  SliceWorkers workers_;
  double filled_xi_[6] = {0, 0, 0, 0, 0, 0};
  bool filled_ = false;
  bool filled_with_jacobians_ = false;
  std::vector<double> residuals_;  // 3 per point.
  std::vector<double> jacobians_;  // 18 per point, row-major 3x6.
  std::vector<char> ok_;           // The cost functions' return values.
};

// Point i's block: the cache's slot i, or `cost` itself when the slot does
// not answer the request. Holds references: the cache and `cost` must
// outlive it.
class CachedPointCost : public ceres::SizedCostFunction<3, 6> {
 public:
  CachedPointCost(const PointEvaluationCache& cache,
                  size_t index,
                  const ceres::CostFunction& cost)
      : cache_(cache), index_(index), cost_(cost) {}

  bool Evaluate(double const* const* parameters,
                double* residuals,
                double** jacobians) const override;

 private:
  const PointEvaluationCache& cache_;
  const size_t index_;
  const ceres::CostFunction& cost_;
};

}  // namespace internal
}  // namespace mlndt
