#pragma once

// The descriptions (common/option_table.h) of the odometry's own options:
// name, unit, range and help of each field, from which the Python keywords
// and their docs are made. The registration's options keep their tables
// (RegistrationOptionsTable); the local map's grid is described by
// LayeredGridOptionsTable and given apart (the tools' grid flags, Python's
// grid=), so LocalMapOptionsTable leaves it out.

#include "mlndt/common/option_table.h"

namespace mlndt {

const OptionTable& LocalMapOptionsTable();
const OptionTable& KeyframeOptionsTable();
const OptionTable& MotionPredictionOptionsTable();
const OptionTable& ConfirmationOptionsTable();
const OptionTable& RecoveryOptionsTable();
// OdometryOptions without `registration` (its fields are the registration's
// keywords beside these).
const OptionTable& OdometryOwnOptionsTable();

}  // namespace mlndt
