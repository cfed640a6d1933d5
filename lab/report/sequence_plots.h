#pragma once

// Figures of a sequence run (mlndt_sequence), drawn with gnuplot.

#include <string>
#include <vector>

#include "lab/runs/sequence_registration.h"

namespace mlndt {

// Writes into `dir` (data and scripts into dir/plot_data):
// errors_translation.png, errors_rotation.png (signed error components per
// input scan, like the paper's Figs. 14-16; with ground truth only),
// trajectory_xy.png (top view against the ground truth) and
// score_vs_iteration.png (score per sampled point against the iteration
// for up to `trace_pairs` pairs, like Figs. 11 and 13, with the translation
// error along the way when the ground truth is known). `pngs` receives the
// file names written. False with *error naming the file that could not be
// written (or gnuplot's failure).
bool WriteSequencePlots(const std::string& gnuplot,
                        const std::string& dir,
                        const std::vector<PairResult>& results,
                        size_t step,
                        int trace_pairs,
                        std::vector<std::string>* pngs,
                        std::string* error);

}  // namespace mlndt
