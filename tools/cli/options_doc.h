#pragma once

// The option reference made from the option tables (option_flags.h): one row
// per flag with the option field(s) it sets, type, default, unit, range and
// help; then the tools' own tables (tool_table_flags.h). docs/options.md is its
// Markdown (mlndt_options writes it; a test checks that the file is current),
// and the JSON form lets the Python tests compare the keywords against the same
// description.

#include <string>

#include "tools/cli/json_output.h"

namespace mlndt {
namespace tools {

// docs/options.md.
std::string OptionsMarkdown();

// {"options": [{"flag", "mlndt_path", "ndt_path", "type", "default", "unit",
//   "range", "help"}, ...], "tool_options":
//   [{"struct", "tool", "options": [{"flag", "field", "type", "default",
//   "unit", "range", "help"}, ...]}, ...]} (the tools' own tables,
//   tool_table_flags.h; "flag" is "" for a field set by a tool flag in
//   another unit).
Json OptionsJson();

}  // namespace tools
}  // namespace mlndt
