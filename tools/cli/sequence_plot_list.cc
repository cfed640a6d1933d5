#include "tools/cli/sequence_plot_list.h"

#include <cstdio>

#include "lab/report/sequence_plots.h"

namespace mlndt {
namespace tools {

bool WriteSequencePlotsAndList(const std::string& gnuplot,
                               const std::string& dir,
                               const std::vector<PairResult>& results,
                               size_t step,
                               int trace_pairs,
                               std::string* error) {
  std::vector<std::string> pngs;
  if (!WriteSequencePlots(
          gnuplot, dir, results, step, trace_pairs, &pngs, error)) {
    return false;
  }
  std::printf("plots: ");
  for (size_t k = 0; k < pngs.size(); ++k) {
    std::printf("%s%s", k ? ", " : "", pngs[k].c_str());
  }
  std::printf("\n");
  return true;
}

}  // namespace tools
}  // namespace mlndt
