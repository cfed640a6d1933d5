#pragma once

// Reading the tools' text output in tests: fields of CSV lines, cells of
// markdown table rows, numbers.

#include <string>
#include <vector>

namespace mlndt {
namespace testing {

// `text` split at every `separator`; a trailing separator gives a final ""
// (so a file ending in '\n' ends with an empty line, and "a,b," has 3 fields).
std::vector<std::string> Split(const std::string& text, char separator);

// The cells of a markdown table row "| a | b |", trimmed.
std::vector<std::string> TableCells(const std::string& line);

// The number `text` holds in full, or NaN (also for "" and trailing junk).
double ToNumber(const std::string& text);

}  // namespace testing
}  // namespace mlndt
