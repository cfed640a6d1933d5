#pragma once

// The option reference made from the option tables (option_flags.h): one row
// per flag with the option field(s) it sets, type, default, unit, range and
// help; then the tools' own tables (tool_table_flags.h). docs/options.md is its
// Markdown (mlndt_options writes it; a test checks that the file is current),
// and the JSON form lets the Python tests compare the keywords against the same
// description. The stub's option TypedDicts come from the same tables.

#include <string>
#include <vector>

#include "mlndt/common/option_table.h"
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

// The Python stub's option TypedDicts (python/mlndt/__init__.pyi, the block
// between "generated" markers that scripts/check_generated.sh compares with
// `mlndt_options --format=options_pyi`):
// `class <Struct>(TypedDict, total=False)` for every table of `roots` and
// every struct nested in them, each once, a nested struct before the first
// struct holding it; one line per field with its Python type (an enum as
// str, its names in a comment).
std::string OptionsStub(const std::vector<const OptionTable*>& roots);

// The tables of the options the Python module takes as dicts: the
// registration's (RegistrationOptions and its nested structs) and the
// odometry's nested structs.
std::vector<const OptionTable*> PythonOptionTables();

}  // namespace tools
}  // namespace mlndt
