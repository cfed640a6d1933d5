#pragma once

// The statistics of one row of mlndt_bench's table (one set of pairs, one
// method) over its repetition rounds.

#include <limits>
#include <vector>

#include "lab/bench/bench_run.h"

namespace mlndt {

// What a table row reports for one set of pairs and one method.
struct BenchRowStats {
  std::vector<double> round_times_ms;  // Per round: mean over the set's pairs.
  std::vector<double> round_align_ms;  // PCL only, same shape.
  double mean_iterations = 0.0;
  // Over the runs that count them (mlndt); NaN when none does (PCL).
  double mean_point_iterations = std::numeric_limits<double>::quiet_NaN();
  double mean_score = 0.0;
  double mean_translation_error_m = 0.0;
  double max_translation_error_m = 0.0;
  double mean_rotation_error_deg = 0.0;
  double max_rotation_error_deg = 0.0;
  int runs = 0;
  int converged = 0;
  int successes = 0;
  double nees_mean = std::numeric_limits<double>::quiet_NaN();
  double nees_median = std::numeric_limits<double>::quiet_NaN();
};

// Over results[round][pair] of one method, for the pairs in `pair_indices`
// (at least one round and one pair).
BenchRowStats SummariseRuns(const std::vector<std::vector<BenchRun>>& results,
                            const std::vector<size_t>& pair_indices);

// A row's round times: their median, min and max, and the median over
// rounds of the per-round ratio reference time / this row's time (NaN
// without a reference).
struct BenchRowTimes {
  double median = 0.0, min = 0.0, max = 0.0;
  double reference_ratio = std::numeric_limits<double>::quiet_NaN();
};

// `reference`: the row whose time is the ratio's numerator (PCL NDT's for
// the table's pcl/ours column), with as many rounds, or null.
BenchRowTimes RowTimes(const BenchRowStats& s, const BenchRowStats* reference);

}  // namespace mlndt
