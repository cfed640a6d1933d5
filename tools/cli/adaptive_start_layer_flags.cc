#include "tools/cli/adaptive_start_layer_flags.h"

#include "lab/runs/adaptive_start_layer_option_table.h"
#include "tools/cli/option_flags.h"

namespace mlndt {
namespace tools {
namespace {

const TableFlags kAdaptiveStartLayerFlags(
    AdaptiveStartLayerOptionsTable(),
    "mlndt_sequence",
    {{"enabled", "adaptive_start_layer"},
     {"max_translation_m", "adaptive_max_translation_m"},
     {"max_rotation_deg", "adaptive_max_rotation_deg"},
     {"fail_rate_thresholds", "adaptive_fail_rate_thresholds"}},
    {},
    &IsSharedFlag);

}  // namespace

const TableFlags& AdaptiveStartLayerFlags() { return kAdaptiveStartLayerFlags; }

}  // namespace tools
}  // namespace mlndt
