#pragma once

// mlndt_scaling's reports of what it measured at every cloud size
// (lab/experiments/scaling_measure.h): the log-log slopes, the markdown
// table, scaling.csv and the gnuplot figure. The tool prints the texts
// (lab/programs/scaling_output.h).

#include <string>
#include <utility>
#include <vector>

#include "lab/experiments/scaling_measure.h"

namespace mlndt {

// Least-squares slope b of log(y) = a + b log(x); NaN with fewer than two
// points or a non-positive value.
double LogLogSlope(const std::vector<double>& x, const std::vector<double>& y);

// The quantities whose slopes are reported, by name, one value per size:
// map, sampling, solve, total, sampled points, finest-layer cells.
std::vector<std::pair<std::string, std::vector<double>>> ScalingSeries(
    const std::vector<SizeResult>& results);

// scaling.csv: one row per size.
bool WriteScalingCsv(const std::string& path,
                     const std::vector<SizeResult>& results,
                     std::string* error);

// scaling.gp / scaling.png in `dir`: log-log time against N per stage (the
// first four `slopes` in the legend), read from dir/scaling.csv, with a
// dashed slope-1 line through the smallest size's total. `title` describes
// the run.
bool WriteScalingPlot(const std::string& gnuplot,
                      const std::string& dir,
                      const std::string& title,
                      const std::vector<SizeResult>& results,
                      const std::vector<double>& slopes,
                      std::string* error);

// The markdown table of the sizes: one row per size, its last column "ok",
// "FAILED" or "LARGE ERROR".
std::string ScalingTableText(const std::vector<SizeResult>& results);

// The log-log slope (LogLogSlope against `sizes`) of every ScalingSeries, in
// its order.
std::vector<double> ScalingSlopes(const std::vector<size_t>& sizes,
                                  const std::vector<SizeResult>& results);

// The slope of every series (`slopes`, ScalingSlopes) and of the solve
// against the sampled points, one line each after a heading.
std::string ScalingSlopesText(const std::vector<size_t>& sizes,
                              const std::vector<SizeResult>& results,
                              const std::vector<double>& slopes);

// One line per size whose solve failed or missed the motion by more than
// the tolerances: "N = 4000: registration FAILED: ..." or "N = 4000:
// recovered motion off by ...".
std::vector<std::string> BrokenSolveLines(
    const std::vector<SizeResult>& results,
    double max_translation_error_m,
    double max_rotation_error_deg);

// "Registration time against cloud size (median of R runs; METHOD,
// BACKEND, SAMPLING sampling)".
std::string ScalingPlotTitle(int repetitions,
                             Method method,
                             const std::string& backend,
                             const std::string& sampling);

// "METHOD, backend B, sampling S, threads T; motion M; median of R runs".
std::string ScalingRunLine(Method method,
                           const std::string& backend,
                           const std::string& sampling,
                           int threads,
                           const std::string& motion,
                           int repetitions);

}  // namespace mlndt
