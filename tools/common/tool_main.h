#pragma once

// The start of every tool's main: usage message, flags, logging.

namespace mlndt {
namespace tools {

// Sets `usage` as the --help text, parses the flags (removing them from
// argv) and starts glog, logging to stderr. With `reject_arguments`, an
// argument left after the flags is reported on stderr as
// "<tool>: unexpected argument 'x' (flags are --name=value)" and false is
// returned (the tool exits with 1).
bool StartTool(const char* usage,
               bool reject_arguments,
               int* argc,
               char*** argv);

}  // namespace tools
}  // namespace mlndt
