#pragma once

// mlndt_bench's --output_plot: per set of pairs, the median time against
// the mean translation error of every configuration, with the Pareto front
// (the configurations no other one beats in both) joined and labelled.

#include <string>
#include <vector>

namespace mlndt {
namespace tools {

struct BenchPlotPoint {
  std::string set;
  std::string label;  // ShortLabel (bench_report.h).
  double time_ms = 0.0;
  double error_m = 0.0;
};

// For each point, whether it is on its set's Pareto front: no point of the
// same set has time <= and error <= with one of them strictly smaller.
std::vector<bool> ParetoFront(const std::vector<BenchPlotPoint>& points);

// Writes png_path + ".dat" (one gnuplot index per set: time, error, front
// 0/1, label; the front's points sorted by time) and png_path + ".gp", and
// runs `gnuplot` to make png_path. False with *error naming the file.
bool WriteBenchPlot(const std::string& gnuplot,
                    const std::string& png_path,
                    const std::vector<BenchPlotPoint>& points,
                    std::string* error);

}  // namespace tools
}  // namespace mlndt
