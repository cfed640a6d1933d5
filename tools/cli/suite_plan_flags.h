#pragma once

// mlndt_suite's flags of SuitePlanOptions' single-value fields
// (table_flags.h, made from SuitePlanOptionsTable): --perturb_count,
// --perturb_seed, --max_pairs_per_set. perturb_translation_m and
// perturb_rotation_deg are set by the tool's --perturb=translation_m,
// rotation_deg. Linking this file gives a tool these flags.

#include "tools/cli/table_flags.h"

namespace mlndt {
namespace tools {

const TableFlags& SuitePlanFlags();

}  // namespace tools
}  // namespace mlndt
