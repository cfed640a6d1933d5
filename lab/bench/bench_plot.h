#pragma once

// mlndt_bench's --output_plot: per set of pairs, the median time against
// the mean translation error of every configuration, with the Pareto front
// (lab/bench/bench_pareto.h) joined and labelled.

#include <string>
#include <vector>

#include "lab/bench/bench_pareto.h"

namespace mlndt {

// Writes png_path + ".dat" (one gnuplot index per set: time, error, front
// 0/1, label; the front's points sorted by time) and png_path + ".gp", and
// runs `gnuplot` to make png_path. False with *error naming the file.
bool WriteBenchPlot(const std::string& gnuplot,
                    const std::string& png_path,
                    const std::vector<BenchPlotPoint>& points,
                    std::string* error);

}  // namespace mlndt
