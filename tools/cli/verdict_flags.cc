#include "tools/cli/verdict_flags.h"

// clang-format off
DEFINE_bool(accept_no_convergence, false,
            "Exit 0 for NO_CONVERGENCE (the iteration cap was reached, the fit passed the "
            "quality check) instead of 1");
DEFINE_bool(accept_unverified, false,
            "Exit 0 for every pose that was written: also LOW_QUALITY, DEGENERATE and "
            "NO_CONVERGENCE instead of 1");
// clang-format on

namespace mlndt {
namespace tools {

bool AcceptedResult(TerminationType termination) {
  switch (termination) {
    case TerminationType::CONVERGENCE:
      return true;
    case TerminationType::NO_CONVERGENCE:
      return FLAGS_accept_no_convergence || FLAGS_accept_unverified;
    case TerminationType::LOW_QUALITY:
    case TerminationType::DEGENERATE:
      return FLAGS_accept_unverified;
    case TerminationType::FAILURE:
      return false;
  }
  return false;
}

}  // namespace tools
}  // namespace mlndt
