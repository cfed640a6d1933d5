#pragma once

// Every tool's flags made from its own option tables (table_flags.h), for
// the option reference (options_doc.h) and the surface test. Linking this
// file registers all of them (mlndt_options refuses them).

#include <vector>

#include "tools/cli/table_flags.h"

namespace mlndt {
namespace tools {

std::vector<const TableFlags*> ToolTableFlags();

}  // namespace tools
}  // namespace mlndt
