#pragma once

// Files written for a sequence run (mlndt_sequence): summary.json, and
// the trajectories with pairs.csv and trace.csv (lab/report/sequence_tables.h).
// The summary's numbers are computed from the same values pairs.csv holds
// (ComputeTotals, lab/runs/sequence_totals.h), printed with 10 significant
// digits in both. Figures: lab/report/sequence_plots.h.

#include <string>
#include <vector>

#include "lab/eval/statistics.h"
#include "lab/report/sequence_tables.h"
#include "lab/runs/scan_store.h"
#include "lab/runs/sequence_registration.h"
#include "tools/cli/json_output.h"
#include "tools/cli/scan_input.h"

namespace mlndt {
namespace tools {

// summary.json (docs/json_schema.md, "mlndt_sequence"): `header` (the
// schema header and the run's settings) followed by the run's totals.
Json SummaryJson(const Json& header, const std::vector<PairResult>& results);

// Where the scans of a run come from, for summary.json (the flags of the
// same names).
struct SequenceSource {
  std::string scans_dir;
  std::string bag;
  std::string topic;
  int start_layer_flag = 0;
};

// The schema header and the run's settings, first in summary.json.
Json SequenceSummaryHeader(const SequenceOptions& options,
                           const SequenceSource& source,
                           size_t num_scans);

// pairs.csv, trace.csv and the trajectories (trajectory_kitti.txt,
// trajectory_tum.txt, with truth gt_trajectory_kitti.txt) into `dir`; the tool
// writes summary.json (SummaryJson) last (output_set.h).
bool WriteSequenceFiles(const std::string& dir,
                        const SequenceOptions& options,
                        const ScanInput& input,
                        const ScanStore& store,
                        const std::vector<PairResult>& results,
                        bool has_truth,
                        std::string* error);

// The failure message when pairs have no usable result (the first of them
// listed), else "".
std::string UnusablePairsMessage(const SequenceOptions& options,
                                 const std::vector<PairResult>& results);

// Every file mlndt_sequence writes into --output_dir, checked before the
// run (a pose or times file there is refused, not overwritten).
std::vector<std::string> SequenceOutputFiles(bool has_truth, bool plots);

}  // namespace tools
}  // namespace mlndt
