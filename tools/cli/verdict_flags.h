#pragma once

// Whether a registration's pose is to be trusted, and the exit code that
// says so (tool_main.h): --accept_no_convergence and --accept_unverified,
// defined in verdict_flags.cc for the tools that report registrations.
//
//   CONVERGENCE                exit 0
//   NO_CONVERGENCE             exit 1; 0 with --accept_no_convergence or
//                              --accept_unverified
//   LOW_QUALITY, DEGENERATE    exit 1; 0 with --accept_unverified
//   FAILURE                    exit 1
// The pose of a result that is not accepted is still reported; a cloud
// moved by it is not written.

#include <gflags/gflags.h>

#include "mlndt/common/types.h"

DECLARE_bool(accept_no_convergence);
DECLARE_bool(accept_unverified);

namespace mlndt {
namespace tools {

// True when the pose of a registration that ended with `termination` is to
// be used (exit 0), given the two flags.
bool AcceptedResult(TerminationType termination);

}  // namespace tools
}  // namespace mlndt
