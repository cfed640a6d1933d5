#pragma once

// How many threads a parallel loop of the library uses: the one place that
// says when work is too small to share (docs/performance.md has the
// measurements behind the numbers).
//
// A parallel loop pays only when each thread's share takes about a
// millisecond on one core or more: the order of a scheduler time slice,
// which is what a woken thread can wait for a core on a shared machine
// (with more runnable threads than cores, as on the 2-core machine of
// docs/performance.md, where smaller shares made 2 threads slower than 1).
// On an idle machine a fork/join costs 5-50 us, so the thresholds below give
// up little there. A loop is split only when every thread gets at least its
// `min_items_per_thread`, derived from each item's measured cost.
//
// The map build and the Ceres evaluation write per-item results or sums in
// an order that does not depend on the thread count, so there the count
// only changes the speed, never the bits; the Newton and LM sums keep
// per-thread partials (the same bits for the same count).

#include <algorithm>
#include <cstdint>

namespace mlndt {

// Residual blocks of the Ceres backend evaluated in parallel
// (solvers/internal/point_evaluation_cache.h): one auto-diff evaluation of
// MlNdtPointCost with its Jacobian takes about 60-100 ns.
constexpr int64_t kMinResidualBlocksPerThread = 16384;

// Points of a score, gradient and Hessian sum of the Newton and LM backends
// and the NDT baseline (cost/internal/score_reduction.h): about 50-100 ns
// a point. These sums are per-thread partials: below this, the one-thread
// bits.
constexpr int64_t kMinScorePointsPerThread = 16384;

// Reference points of the map build (grid/layered_grid.cc): each of its
// parallel loops (bounds, binning, moments) takes about 5 ns a point.
constexpr int64_t kMinMapPointsPerThread = 262144;

// Cells of a map layer computed in parallel (mean, covariance and its
// eigen-decomposition, about 1 us a cell).
constexpr int64_t kMinMapCellsPerThread = 1024;

// Threads for `items` work items when `max_threads` are allowed: as many as
// give each at least `min_items_per_thread` items, at least 1.
inline int ThreadsFor(int64_t items,
                      int64_t min_items_per_thread,
                      int max_threads) {
  const int64_t affordable = items / std::max<int64_t>(1, min_items_per_thread);
  return static_cast<int>(
      std::max<int64_t>(1, std::min<int64_t>(affordable, max_threads)));
}

}  // namespace mlndt
