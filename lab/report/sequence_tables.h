#pragma once

// Tables of a sequence run (mlndt_sequence): pairs.csv, trace.csv and the
// totals on stdout. The totals are computed from the values pairs.csv holds
// (ComputeTotals, lab/runs/sequence_totals.h). Figures:
// sequence_plots.h; summary.json: tools/cli/sequence_output.h.

#include <string>
#include <vector>

#include "lab/runs/scan_store.h"
#include "lab/runs/sequence_registration.h"

namespace mlndt {

// pairs.csv: one row per pair. Error columns (signed components of the
// error transform, norms, success flags) are empty without ground truth.
bool WriteSequencePairsCsv(const std::string& path,
                           const ScanStore& store,
                           const std::vector<PairResult>& results,
                           std::string* error);

// trace.csv: every iteration of every pair.
bool WriteSequenceTraceCsv(const std::string& path,
                           const std::vector<PairResult>& results,
                           std::string* error);

// The run's totals on stdout (pairs, success rates, errors, times) and the
// output folder.
void PrintSequenceTotals(const SequenceOptions& options,
                         const std::vector<PairResult>& results,
                         const std::string& output_dir);

}  // namespace mlndt
