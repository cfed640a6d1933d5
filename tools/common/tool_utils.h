#pragma once

// Small helpers shared by the tools: numbers for tables, CSV and data
// files, the command line, peak memory.

#include <string>

namespace mlndt {
namespace tools {

// `value` with `precision` decimals for tables; "–" when not finite.
std::string Fmt(double value, int precision);

// A number for CSV and data files: 10 significant digits, "nan" when not
// finite.
std::string Num(double value);

// `text` as one CSV field (quoted when it holds a comma, quote or newline).
std::string CsvField(const std::string& text);

// The command line the tool was started with (gflags' argv, space-joined).
std::string CommandLine();

// The process's peak resident set size so far [bytes] (getrusage; Linux
// reports ru_maxrss in KiB).
double PeakResidentBytes();

}  // namespace tools
}  // namespace mlndt
