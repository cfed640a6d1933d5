#pragma once

// The claim "10-20 % of the input scan is sufficient for successful
// convergence" (Section 4): uniform random sampling of 1-30 % of the input,
// from the identity and from the prior, for NDT and ML-NDT (paper preset
// and defaults).

#include <string>

#include "lab/experiments/report_context.h"

namespace mlndt {
namespace experiments {

std::string SamplingSection(const ReportContext& c);

}  // namespace experiments
}  // namespace mlndt
