#pragma once

// Numbers and fields as the lab's reports and the tools write them: tables
// (Fmt), CSV and data files (Num, CsvField) and durations (FormatDuration).

#include <string>

namespace mlndt {

// `value` with `precision` decimals for tables; "–" when not finite.
std::string Fmt(double value, int precision);

// A number for CSV and data files: 10 significant digits, "nan" when not
// finite.
std::string Num(double value);

// `text` as one CSV field (quoted when it holds a comma, quote or newline).
std::string CsvField(const std::string& text);

// "1m05s" (or "12s", "1h02m") for progress lines and reports; "?" when not
// finite or negative (before any run).
std::string FormatDuration(double seconds);

}  // namespace mlndt
