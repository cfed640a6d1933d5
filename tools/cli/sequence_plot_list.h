#pragma once

// mlndt_sequence's --plots: the figures (lab/report/sequence_plots.h) and
// the line that lists them.

#include <string>
#include <vector>

#include "lab/runs/sequence_registration.h"

namespace mlndt {
namespace tools {

// WriteSequencePlots, then "plots: a.png, b.png, ..." on stdout.
bool WriteSequencePlotsAndList(const std::string& gnuplot,
                               const std::string& dir,
                               const std::vector<PairResult>& results,
                               size_t step,
                               int trace_pairs,
                               std::string* error);

}  // namespace tools
}  // namespace mlndt
