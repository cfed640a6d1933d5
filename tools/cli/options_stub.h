#pragma once

// The Python stub's option TypedDicts (python/mlndt/__init__.pyi) made from
// the option tables (option_table.h): a block between "generated" markers
// that scripts/check_generated.sh compares with
// `mlndt_options --format=options_pyi`.

#include <string>
#include <vector>

#include "mlndt/common/option_table.h"

namespace mlndt {
namespace tools {

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
