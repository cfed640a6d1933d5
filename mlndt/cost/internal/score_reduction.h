#pragma once

// The one parallel reduction of a score, its gradient and Hessian (J^T J and
// J^T e in the Gauss-Newton forms) over the input points: the ML-NDT score
// (cost/score.cc, Eqs. 12-14) and the conventional NDT's Gaussian score
// (ndt/gaussian_score.cc, Magnusson Eq. 6.12) sum their per-point terms with
// it.

#include <omp.h>

#include <cstddef>
#include <vector>

#include "mlndt/common/thread_budget.h"
#include "mlndt/cost/score.h"

namespace mlndt {
namespace internal {

// Calls accumulate(begin, end, &partial) for `threads` contiguous slices of
// [0, n) (slice t is [n t / threads, n (t + 1) / threads)), one OpenMP thread
// each, and sums the partial evaluations in slice order. The slices and the
// order of the sum do not depend on the scheduler: a given thread count
// always gives the same bits. `threads` >= 1.
//
// Fewer points than kMinScorePointsPerThread a thread (thread_budget.h) are
// summed on fewer threads: a small problem gets the one-thread bits.
template <typename AccumulateSlice>
ScoreEvaluation ReduceScoreInSlices(size_t n,
                                    int max_threads,
                                    const AccumulateSlice& accumulate) {
  const int threads = ThreadsFor(
      static_cast<int64_t>(n), kMinScorePointsPerThread, max_threads);
  std::vector<ScoreEvaluation> partial(static_cast<size_t>(threads));
#pragma omp parallel for num_threads(threads) \
    schedule(static, 1) if (threads > 1)
  for (int t = 0; t < threads; ++t) {
    const size_t begin =
        n * static_cast<size_t>(t) / static_cast<size_t>(threads);
    const size_t end =
        n * static_cast<size_t>(t + 1) / static_cast<size_t>(threads);
    accumulate(begin, end, &partial[static_cast<size_t>(t)]);
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

}  // namespace internal
}  // namespace mlndt
