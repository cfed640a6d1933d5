#pragma once

// mlndt_odometry's flags of OdometryOptions' own fields (table_flags.h, made
// from OdometryOwnOptionsTable): named as the fields' paths
// (--local_map_max_keyframes, --keyframes_min_translation_m,
// --prediction_max_translation_m, --confirmation_enabled, --gate_factor).
// The registration's flags set OdometryOptions::registration, whose defaults
// are OdometryRegistrationOptions(). Linking this file gives a tool these
// flags.

#include "tools/cli/table_flags.h"

namespace mlndt {
namespace tools {

const TableFlags& OdometryFlags();

}  // namespace tools
}  // namespace mlndt
