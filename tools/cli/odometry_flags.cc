#include "tools/cli/odometry_flags.h"

#include "mlndt/odometry/odometry_option_tables.h"
#include "tools/cli/option_flags.h"

namespace mlndt {
namespace tools {
namespace {

const TableFlags kOdometryFlags(
    OdometryOwnOptionsTable(),
    "mlndt_odometry",
    {},
    {},
    {{"local_map_keyframes", "local_map_max_keyframes"},
     {"local_map_radius", "local_map_radius_m"},
     {"keyframe_distance", "keyframes_min_translation_m"},
     {"keyframe_angle", "keyframes_min_rotation_deg"},
     {"max_uncertainty_m", "prediction_max_translation_m"},
     {"max_uncertainty_deg", "prediction_max_rotation_deg"},
     {"confirm", "confirmation_enabled"},
     {"confirm_fraction", "confirmation_min_correction_fraction"},
     {"confirm_last_scan", "confirmation_check_last_scan"}},
    &IsSharedFlag);

}  // namespace

const TableFlags& OdometryFlags() { return kOdometryFlags; }

}  // namespace tools
}  // namespace mlndt
