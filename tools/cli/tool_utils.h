#pragma once

// Small helpers shared by the tools: the command line, peak memory (numbers
// for tables and CSV files: lab/report/text_format.h).

#include <string>

namespace mlndt {
namespace tools {

// The command line the tool was started with (gflags' argv, space-joined).
std::string CommandLine();

// The process's peak resident set size so far [bytes] (getrusage; Linux
// reports ru_maxrss in KiB).
double PeakResidentBytes();

}  // namespace tools
}  // namespace mlndt
