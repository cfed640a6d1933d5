#include "lab/eval/verdict_counts.h"

namespace mlndt {
namespace {

// Every verdict, in report order: usable first.
constexpr std::array<TerminationType, 5> kVerdicts = {
    TerminationType::CONVERGENCE,
    TerminationType::NO_CONVERGENCE,
    TerminationType::LOW_QUALITY,
    TerminationType::DEGENERATE,
    TerminationType::FAILURE};

size_t Index(TerminationType type) {
  for (size_t k = 0; k < kVerdicts.size(); ++k) {
    if (kVerdicts[k] == type) return k;
  }
  return kVerdicts.size() - 1;  // Unknown values count as FAILURE.
}

}  // namespace

const std::array<TerminationType, 5>& VerdictCounts::Verdicts() {
  return kVerdicts;
}

void VerdictCounts::Add(TerminationType type) {
  ++counts_[Index(type)];
  ++total_;
  usable_ += IsUsableTermination(type);
}

size_t VerdictCounts::count(TerminationType type) const {
  return counts_[Index(type)];
}

std::string VerdictCounts::Line() const {
  std::string out;
  for (size_t k = 0; k < kVerdicts.size(); ++k) {
    out += (k ? ", " : "") +
           std::string(TerminationTypeToString(kVerdicts[k])) + " " +
           std::to_string(counts_[k]);
  }
  return out;
}

}  // namespace mlndt
