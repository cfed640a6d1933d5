#pragma once

// mlndt_localize's flags of LocalizerOptions' own fields (table_flags.h,
// made from LocalizerOwnOptionsTable): --motion_model. Linking this file
// gives a tool these flags.

#include "tools/cli/table_flags.h"

namespace mlndt {
namespace tools {

const TableFlags& LocalizerFlags();

}  // namespace tools
}  // namespace mlndt
