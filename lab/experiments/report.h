#pragma once

// OUT/README_RESULTS.md (one section per table and figure of the paper's
// Section 5, in the paper's order) and OUT/summary.json (the headline
// numbers), from the runs of one invocation.

#include <string>
#include <vector>

#include "lab/experiments/report_context.h"
#include "lab/experiments/trace_experiment.h"

namespace mlndt {
namespace experiments {

struct ReportHeader {
  std::string command;  // The command line.
  bool quick = false;
  std::string data_dir;
  std::vector<std::string> missing;  // Data sets not found.
  double run_seconds = 0.0;          // Registrations' wall time.
  size_t runs = 0;
};

// Builds README_RESULTS.md and summary.json into c.files.
void BuildReport(const ReportHeader& header,
                 const ReportContext& c,
                 const TraceExperiment& trace);

}  // namespace experiments
}  // namespace mlndt
