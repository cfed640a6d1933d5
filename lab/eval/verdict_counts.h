#pragma once

// Results counted by verdict, for the printed summaries and summary.json of
// the tools that run many registrations (mlndt_localize, mlndt_sequence;
// the JSON form is tools/cli/verdict_counts_json.h): one count per
// TerminationType (CONVERGENCE, NO_CONVERGENCE, LOW_QUALITY,
// DEGENERATE, FAILURE; every key always present) and the usable ones by the
// library's one definition (IsUsableTermination, mlndt/common/types.h). A
// tool exits 1 when unusable() > 0.

#include <array>
#include <cstddef>
#include <string>

#include "mlndt/common/types.h"

namespace mlndt {

class VerdictCounts {
 public:
  // Every verdict in report order, usable first: CONVERGENCE,
  // NO_CONVERGENCE, LOW_QUALITY, DEGENERATE, FAILURE.
  static const std::array<TerminationType, 5>& Verdicts();

  void Add(TerminationType type);

  size_t count(TerminationType type) const;
  size_t total() const { return total_; }
  size_t usable() const { return usable_; }
  size_t unusable() const { return total_ - usable_; }

  // "CONVERGENCE 3, NO_CONVERGENCE 0, LOW_QUALITY 5, DEGENERATE 0,
  // FAILURE 0".
  std::string Line() const;

 private:
  std::array<size_t, 5> counts_{};
  size_t total_ = 0;
  size_t usable_ = 0;
};

}  // namespace mlndt
