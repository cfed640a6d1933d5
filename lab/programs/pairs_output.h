#pragma once

// mlndt_pairs' report: one table line and one --output_csv row a
// registration (lab/experiments/gap_pairs.h), and the totals.

#include <sstream>
#include <string>

#include "lab/eval/verdict_counts.h"
#include "lab/experiments/gap_pairs.h"

namespace mlndt {
namespace lab {

// The totals of a run so far: counts, times and verdicts.
struct PairsTally {
  int total = 0;
  int successes = 0;
  std::vector<double> times_ms;
  VerdictCounts verdicts;
  void Add(const GapPairRun& run);
};

// The table's header line and one line a run.
void PrintPairsHeader();
void PrintPairRow(const GapPairRun& run);

// The CSV header and one row a run.
std::string PairsCsvHeader();
void AppendPairCsvRow(const GapPairRun& run, std::ostringstream* csv);

// "success: s / n (p %), median time t ms" and the verdicts line.
void PrintPairsTally(const PairsTally& tally);

}  // namespace lab
}  // namespace mlndt
