#include "lab/eval/trajectory_evaluation_option_table.h"

#include <limits>

#include "lab/eval/trajectory_evaluation.h"

namespace mlndt {

const EnumTable& TrajectoryAlignmentTable() {
  using A = TrajectoryAlignment;
  // SE3 first: the default, first in the messages' list of choices.
  static const EnumTable table({{static_cast<int>(A::SE3), "SE3"},
                                {static_cast<int>(A::SIM3), "SIM3"},
                                {static_cast<int>(A::FIRST_POSE), "FIRST_POSE"},
                                {static_cast<int>(A::NONE), "NONE"}});
  return table;
}

const EnumTable& PoseAssociationTable() {
  using P = PoseAssociation;
  static const EnumTable table({{static_cast<int>(P::AUTO), "AUTO"},
                                {static_cast<int>(P::INDEX), "INDEX"},
                                {static_cast<int>(P::TIMESTAMP), "TIMESTAMP"}});
  return table;
}

const OptionTable& KittiSegmentOptionsTable() {
  using S = KittiSegmentOptions;
  static const OptionTable table =
      OptionTableBuilder<S>("KittiSegmentOptions")
          .DoubleList("lengths_m",
                      &S::lengths_m,
                      "m",
                      LeftOpen(0.0, 1e9),
                      "KITTI devkit segment lengths, each once (the devkit: "
                      "100 to 800).")
          .Int("first_frame_step",
               &S::first_frame_step,
               AtLeast(1),
               "A segment's first frame every this many frames (the "
               "devkit: 10, one second).")
          .Build();
  return table;
}

const OptionTable& TrajectoryEvaluationOptionsTable() {
  using S = TrajectoryEvaluationOptions;
  static const OptionTable table =
      OptionTableBuilder<S>("TrajectoryEvaluationOptions")
          .Enum("alignment",
                &S::alignment,
                TrajectoryAlignmentTable(),
                "ATE: how the estimate is aligned to the reference.")
          .Int("delta",
               &S::delta,
               AtLeast(1),
               "RPE: frames (associated poses) between the two poses of a "
               "motion.")
          .Enum("association",
                &S::association,
                PoseAssociationTable(),
                "How poses are paired: auto (by time stamp when both files "
                "have stamps, else by index), index or timestamp.")
          .Double("max_time_difference_s",
                  &S::max_time_difference_s,
                  "s",
                  LeftOpen(0.0, std::numeric_limits<double>::infinity()),
                  "Timestamp association: largest |dt| of a pair.")
          .Struct("segments",
                  &S::segments,
                  KittiSegmentOptionsTable(),
                  "The KITTI devkit's segment errors.")
          .Validator(&S::IsValid)
          .Build();
  return table;
}

}  // namespace mlndt
