#pragma once

// The JSON form of VerdictCounts (lab/eval/verdict_counts.h) in the tools'
// summary.json files.

#include "lab/eval/verdict_counts.h"
#include "tools/cli/json_output.h"

namespace mlndt {
namespace tools {

// {"CONVERGENCE": 3, ..., "FAILURE": 0}, every verdict a key, in report
// order.
Json VerdictCountsJson(const VerdictCounts& counts);

}  // namespace tools
}  // namespace mlndt
