#pragma once

// Flags registered with gflags from option tables at run time (what the
// DEFINE_ macros do at compile time), for the shared flags (option_flags.h)
// and a tool's table flags (table_flags.h). Apart from option_flags.cc so
// that a tool with table flags only does not link the shared ones.

#include <string>

#include "mlndt/common/option_table.h"

namespace mlndt {
namespace tools {

// Registers --<name> with gflags as if DEFINE_d in `file` (a string that
// outlives the program; --help groups flags by it): a bool, int32, uint64,
// double or (lists, enums) string flag by `type`, whose default is
// `default_text` (OptionField::Format's text).
void RegisterOptionFlag(const std::string& name,
                        const std::string& help,
                        const char* file,
                        OptionType type,
                        const std::string& default_text);

}  // namespace tools
}  // namespace mlndt
