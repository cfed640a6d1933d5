#pragma once

// Table 9: the start layer (working layers n-2..n, n-1..n, n) against the
// initialisation Z_i = c Z_ref, c in {0.9, 0.6, 0.3, 0}, under the paper
// preset and the defaults; fail rate by the paper's rule (> 1 m or
// > 15 deg from the reference), time, and error norm of the rest.

#include <string>

#include "lab/experiments/report_context.h"

namespace mlndt {
namespace experiments {

std::string Table9Section(const ReportContext& c);

}  // namespace experiments
}  // namespace mlndt
