#include "lab/experiments/report_context.h"

#include <cmath>
#include <set>

#include "lab/report/text_format.h"

namespace mlndt {
namespace experiments {

std::vector<const RunRecord*> Select(const ReportContext& c,
                                     const std::string& experiment,
                                     const std::string& dataset,
                                     const std::string& config) {
  std::vector<const RunRecord*> out;
  for (const RunRecord& r : *c.records) {
    if (!experiment.empty() && r.experiment != experiment) continue;
    if (!dataset.empty() && r.dataset != dataset) continue;
    if (!config.empty() && r.config != config) continue;
    out.push_back(&r);
  }
  return out;
}

double PercentValue(size_t part, size_t whole) {
  return whole == 0 ? NAN : 100.0 * part / whole;
}

std::string Percent(size_t part, size_t whole) {
  return whole == 0 ? "–" : Fmt(PercentValue(part, whole), 1) + " %";
}

const ExperimentDataset* FindDataset(const ReportContext& c,
                                     const std::string& name) {
  for (const ExperimentDataset& set : *c.datasets) {
    if (set.name == name) return &set;
  }
  return nullptr;
}

std::vector<std::string> SequencePairsOf(const ReportContext& c,
                                         const ExperimentDataset& set) {
  std::set<std::string> ran;
  for (const RunRecord* r : Select(c, "accuracy", set.name, "ndt"))
    ran.insert(r->pair);
  const std::vector<std::string> all = set.PairsByStep();
  if (all.empty()) return {};
  const ReferencePair& first = set.pairs.at(all.front());
  std::vector<std::string> out;
  for (const std::string& key :
       set.PairsWithStep(first.input_index - first.reference_index)) {
    if (ran.count(key)) out.push_back(key);
  }
  return out;
}

std::string SequenceDataset(const ReportContext& c) {
  std::string best;
  size_t most = 0;
  for (const ExperimentDataset& set : *c.datasets) {
    const size_t n = SequencePairsOf(c, set).size();
    if (n > most) {
      most = n;
      best = set.name;
    }
  }
  return best;
}

std::vector<std::string> SequencePairs(const ReportContext& c) {
  const ExperimentDataset* set = FindDataset(c, SequenceDataset(c));
  return set ? SequencePairsOf(c, *set) : std::vector<std::string>{};
}

}  // namespace experiments
}  // namespace mlndt
