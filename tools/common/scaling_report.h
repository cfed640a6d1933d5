#pragma once

// What mlndt_scaling measures at one cloud size, and its reports: the
// log-log slopes, scaling.csv and the gnuplot figure.

#include <string>
#include <utility>
#include <vector>

#include "lab/experiments/scaling_measure.h"

namespace mlndt {
namespace tools {

// Least-squares slope b of log(y) = a + b log(x); NaN with fewer than two
// points or a non-positive value.
double LogLogSlope(const std::vector<double>& x, const std::vector<double>& y);

// The quantities whose slopes are reported, by name, one value per size:
// map, sampling, solve, total, sampled points, finest-layer cells.
std::vector<std::pair<std::string, std::vector<double>>> Series(
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

// The markdown table of the sizes on stdout.
void PrintScalingTable(const std::vector<SizeResult>& results);

// Prints the slope of every series and of the solve against the sampled
// points; returns the series' slopes.
std::vector<double> PrintScalingSlopes(const std::vector<size_t>& sizes,
                                       const std::vector<SizeResult>& results);

// Names on stderr every size whose solve failed or missed the motion by
// more than the tolerances.
void PrintBrokenSolves(const std::vector<SizeResult>& results,
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

}  // namespace tools
}  // namespace mlndt
