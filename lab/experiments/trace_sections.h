#pragma once

// Figs. 10-13 from the trace experiment (trace_experiment.h).

#include <string>

#include "lab/experiments/report_context.h"
#include "lab/experiments/trace_experiment.h"

namespace mlndt {
namespace experiments {

// The four sections; `trace` may be empty (no data set for it), and then
// each says so.
std::string TraceSections(const ReportContext& c, const TraceExperiment& t);

}  // namespace experiments
}  // namespace mlndt
