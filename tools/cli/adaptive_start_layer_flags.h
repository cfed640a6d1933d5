#pragma once

// mlndt_sequence's flags of AdaptiveStartLayerOptions (table_flags.h, made
// from AdaptiveStartLayerOptionsTable), prefixed as the struct is
// SequenceOptions::adaptive: --adaptive_start_layer (enabled),
// --adaptive_max_translation_m, --adaptive_max_rotation_deg,
// --adaptive_fail_rate_thresholds. Linking this file gives a tool these
// flags.

#include "tools/cli/table_flags.h"

namespace mlndt {
namespace tools {

const TableFlags& AdaptiveStartLayerFlags();

}  // namespace tools
}  // namespace mlndt
