#pragma once

// What mlndt_bench measures and reports: one run's result, a table row's
// statistics over rounds, the markdown table and the CSV rows.

#include <limits>
#include <string>
#include <vector>

#include "tools/common/bench_configurations.h"

namespace mlndt {
namespace tools {

// The result of one registration.
struct BenchRun {
  double time_ms = 0.0;
  double align_ms = 0.0;  // PCL only: align() alone.
  int iterations = 0;
  double score = std::numeric_limits<double>::quiet_NaN();
  double translation_error_m = 0.0;
  double rotation_error_deg = 0.0;
  // Stopped on its convergence test, not on an iteration cap.
  bool converged = false;
  bool success = false;
  // e^T P^-1 e against the reference (mlndt_bench.cc); NaN when the run has
  // no usable covariance (and for PCL).
  double nees = std::numeric_limits<double>::quiet_NaN();
};

// What a table row reports for one set of pairs and one method.
struct BenchRowStats {
  std::vector<double> round_times_ms;  // Per round: mean over the set's pairs.
  std::vector<double> round_align_ms;  // PCL only, same shape.
  double mean_iterations = 0.0;
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

// Over results[round][pair] of one method, for the pairs in `pair_indices`.
BenchRowStats SummariseRuns(const std::vector<std::vector<BenchRun>>& results,
                            const std::vector<size_t>& pair_indices);

// How a row names its method (empty: does not apply).
struct BenchMethodLabels {
  std::string method = "pcl_ndt";
  std::string defaults, backend, sampling, start, solver, region;
  std::string minimizer, jacobians, loss;  // loss: "cauchy@1.5", "none".
  std::string threads = "1";
  bool is_pcl = true;
};

BenchMethodLabels ConfigurationLabels(const BenchConfiguration& c);
// pcl::NDT on clouds voxel-filtered with `leaf_size_m`.
BenchMethodLabels PclLabels(double leaf_size_m);

// The configuration in one short line (plots): backend, minimizer,
// Jacobians, loss, linear solver, trust region, sampling, start layer,
// threads, without the parts that do not apply.
std::string ShortLabel(const BenchMethodLabels& labels);

// `value` printed with `format`; "-" when not finite.
std::string BenchFormat(const char* format, double value);

// The markdown table's header, and one row (`pcl`: PCL's row for the
// pcl/ours ratio, or null).
std::vector<std::string> BenchTableHeader();
std::vector<std::string> BenchTableRow(const std::string& set,
                                       const BenchMethodLabels& labels,
                                       const BenchRowStats& s,
                                       const BenchRowStats* pcl);

// The CSV's header line (with its newline) and one row (without).
std::string BenchCsvHeader();
std::string BenchCsvRow(const std::string& set,
                        const BenchMethodLabels& labels,
                        const BenchRowStats& s,
                        const BenchRowStats* pcl);

// Prints rows (the first is the header) as a markdown table with padded
// columns.
void PrintMarkdownTable(const std::vector<std::vector<std::string>>& rows);

}  // namespace tools
}  // namespace mlndt
