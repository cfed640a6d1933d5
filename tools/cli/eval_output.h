#pragma once

// mlndt_eval's report: the markdown table and the KITTI segment lines on
// stdout, and --output_json (docs/json_schema.md, "mlndt_eval").

#include <string>
#include <vector>

#include "lab/eval/reference_chain.h"
#include "lab/eval/trajectory_evaluation.h"
#include "tools/cli/json_output.h"

namespace mlndt {
namespace tools {

// The header line names the alignment as given (`alignment_flag`).
void PrintEvaluations(const TrajectoryEvaluationOptions& options,
                      const std::string& alignment_flag,
                      const EvaluationReference& reference,
                      const std::vector<TrajectoryEvaluation>& results);

// "chained N poses (scans a..b[: list]) from PAIRS -> OUT".
void PrintChain(const ReferenceChain& chain,
                const std::string& pairs_path,
                const std::string& output);

Json EvaluationsJson(const TrajectoryEvaluationOptions& options,
                     const EvaluationReference& reference,
                     const std::vector<TrajectoryEvaluation>& results);

}  // namespace tools
}  // namespace mlndt
