#include "lab/programs/pairs_output.h"

#include <algorithm>
#include <cstdio>

#include "lab/eval/statistics.h"

namespace mlndt {
namespace lab {

void PairsTally::Add(const GapPairRun& run) {
  ++total;
  successes += run.success;
  times_ms.push_back(run.time_ms);
  verdicts.Add(run.termination);
}

void PrintPairsHeader() {
  std::printf("%-4s %-4s %-3s %-24s %10s %10s %4s %5s %8s\n",
              "ref",
              "in",
              "gap",
              "init",
              "err_t[m]",
              "err_r[deg]",
              "ok",
              "iters",
              "time[ms]");
}

void PrintPairRow(const GapPairRun& run) {
  std::printf("%-4zu %-4zu %-3zu %-24s %10.4f %10.4f %4s %5d %8.1f\n",
              run.reference,
              run.input,
              run.gap,
              run.start.c_str(),
              run.translation_error_m,
              run.rotation_error_deg,
              run.success ? "yes" : "NO",
              run.iterations,
              run.time_ms);
}

std::string PairsCsvHeader() {
  return "reference,input,gap,perturbation,translation_error_m,rotation_"
         "error_deg,success,"
         "termination,iterations,time_ms\n";
}

void AppendPairCsvRow(const GapPairRun& run, std::ostringstream* csv) {
  *csv << run.reference << "," << run.input << "," << run.gap << ",\""
       << run.start << "\"," << run.translation_error_m << ","
       << run.rotation_error_deg << "," << run.success << ","
       << TerminationTypeToString(run.termination) << "," << run.iterations
       << "," << run.time_ms << "\n";
}

void PrintPairsTally(const PairsTally& tally) {
  std::printf("success: %d / %d (%.1f %%), median time %.1f ms\n",
              tally.successes,
              tally.total,
              100.0 * tally.successes / std::max(1, tally.total),
              ComputeStats(tally.times_ms).median);
  std::printf("verdicts: %s\n", tally.verdicts.Line().c_str());
}

}  // namespace lab
}  // namespace mlndt
