#pragma once

// The start of every tool's main: usage message, flags, logging, --help and
// --version, and the exit codes every tool shares.

#include <string>
#include <vector>

namespace mlndt {
namespace tools {

// Exit codes, the same in every tool (README, "Exit codes"):
//  0 success;
//  1 the run failed: a registration FAILED or its result is not to be used
//    (verdict_flags.h), or a result could not be written;
//  2 usage or misconfiguration: a flag, an argument or an input refused
//    before any work, with a message naming it.
constexpr int kExitOk = 0;
constexpr int kExitFailed = 1;
constexpr int kExitUsage = 2;

// Print "<tool>: <message>" on stderr and return kExitFailed (the run
// failed, its result is not to be used) or kExitUsage (a flag, argument or
// input refused before any work).
int Fail(const std::string& tool, const std::string& message);
int Refuse(const std::string& tool, const std::string& message);

// The exit-code paragraph of the usage texts.
extern const char kExitCodesHelp[];

// Sets `usage` as the --help text, parses the flags (removing them from
// argv) and starts glog, logging to stderr.
//  - --help (or -h) prints `usage` (and kExitCodesHelp when `usage` has
//    no "Exit codes" paragraph) and the flags defined in the tool's own
//    file and in tools/cli/ (the shared registration flags among them)
//    with their defaults, and exits with 0; --helpfull lists every flag,
//    glog's and gflags' included.
//  - --version prints "mlndt <PROJECT_VERSION>" and exits with 0.
// A tool reading scans into an output folder takes its data as an argument
// and has a default output folder (data_argument.h). With
// `reject_arguments`, an argument left after the flags is reported on
// stderr as "<tool>: unexpected argument 'x' (flags are --name=value)" and
// false is returned (the tool exits with kExitUsage).
bool StartTool(const char* usage,
               bool reject_arguments,
               int* argc,
               char*** argv);

// What is left in argv after the flags of a tool with one subcommand.
enum class ToolArguments {
  NONE,        // No argument: the tool's main run.
  SUBCOMMAND,  // argv[1] is `name`, followed by `num_args` arguments.
  MISUSE,      // Anything else; reported on stderr (exit kExitUsage).
};

// Reports "<tool>: usage: <usage>" for the subcommand with the wrong number
// of arguments, and "<tool>: unexpected argument 'x' (flags are
// --name=value; the one subcommand is '<synopsis>')" for another argument.
ToolArguments ParseSubcommand(const std::string& tool,
                              int argc,
                              char** argv,
                              const std::string& name,
                              int num_args,
                              const std::string& usage,
                              const std::string& synopsis);

// Shared flags (tools/cli/) that the tool refuses: --help does not list
// them. Call before StartTool.
void HideFlagsFromHelp(const std::vector<std::string>& flags);

// Shared flags (tools/cli/) that the tool links but does not read:
// --help leaves them out and StartTool refuses each one given with
// "<tool>: --<flag> <reason>" (the tool exits with kExitUsage), so that no
// flag is silently ignored. Call before StartTool.
void RefuseUnreadFlags(const std::vector<std::string>& flags,
                       const std::string& reason);

// The option path of a shared flag made from the option tables
// ("grid.finest_cell_size_m"; "" for another flag), for --help's headings.
// Set by option_flags.cc when a tool links it: tool_main.cc does not refer
// to those flags, so a program without them does not link them.
using OptionPathOfFlag = std::string (*)(const std::string& flag);
void SetOptionPathOfFlag(OptionPathOfFlag lookup);

// The main's file of `tool`: "lab/programs/<tool>.cc" for a lab program,
// "tools/<tool>.cc" for a tool.
std::string MainFile(const std::string& tool);

}  // namespace tools
}  // namespace mlndt
