#pragma once

// The descriptions (mlndt/common/option_table.h) of a trajectory
// evaluation's options (trajectory_evaluation.h): name, unit, range and help
// of each field, from which mlndt_eval's flags, their checks and the option
// reference are made; and the enum tables of the alignment and the
// association (their names as StringToTrajectoryAlignment and
// StringToPoseAssociation read them).

#include "mlndt/common/enum_table.h"
#include "mlndt/common/option_table.h"

namespace mlndt {

const EnumTable& TrajectoryAlignmentTable();
const EnumTable& PoseAssociationTable();
const OptionTable& KittiSegmentOptionsTable();
const OptionTable& TrajectoryEvaluationOptionsTable();

}  // namespace mlndt
