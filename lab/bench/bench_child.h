#pragma once

// One registration in a child process, for mlndt_bench's one-shot times: a
// fork()ed child runs it and sends the estimate back through a pipe. The
// child's allocations touch fresh pages, as a new process's do, so its time
// is that of a tool that registers one pair and exits (the clouds, loaded
// once by the parent, are shared copy-on-write and not timed).
//
// libgomp's thread pool does not survive a fork: the parent must not have
// run an OpenMP region with more than one thread before (mlndt_bench runs
// its one-shot rounds first, before any registration in the parent).

#include <functional>
#include <string>

#include "lab/bench/bench_run.h"

namespace mlndt {

// False with *error when the child cannot be started or dies before it
// reports.
bool RunInChildProcess(const std::function<BenchEstimate()>& run,
                       BenchEstimate* estimate,
                       std::string* error);

}  // namespace mlndt
