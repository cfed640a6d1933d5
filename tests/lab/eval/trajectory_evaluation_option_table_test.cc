// TrajectoryEvaluationOptions::IsValid: the ranges and enum values of
// TrajectoryEvaluationOptionsTable (the KITTI segments' by their path), and
// EvaluateTrajectory refusing options out of range before any work.

#include "lab/eval/trajectory_evaluation_option_table.h"

#include <gtest/gtest.h>

#include "lab/eval/trajectory_evaluation.h"

namespace mlndt {
namespace {

TEST(TrajectoryEvaluationOptions, IsValidChecksTheTable) {
  std::string error;
  EXPECT_TRUE(TrajectoryEvaluationOptions().IsValid(&error)) << error;
  TrajectoryEvaluationOptions options;
  options.delta = 0;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_EQ(error, "invalid option: delta = 0; it must be >= 1");
  options = TrajectoryEvaluationOptions();
  options.max_time_difference_s = 0.0;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_EQ(error, "invalid option: max_time_difference_s = 0; it must be > 0");
  options = TrajectoryEvaluationOptions();
  options.segments.first_frame_step = 0;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_EQ(error,
            "invalid option: segments.first_frame_step = 0; it must be >= 1");
  options = TrajectoryEvaluationOptions();
  options.alignment = static_cast<TrajectoryAlignment>(99);
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_NE(error.find("invalid option: alignment = 99 is not a value"),
            std::string::npos)
      << error;
}

TEST(TrajectoryEvaluationOptions, EvaluateRefusesThemFirst) {
  TrajectoryEvaluationOptions options;
  options.delta = -2;
  EvaluationReference reference;
  TrajectoryEvaluation result;
  std::string error;
  EXPECT_FALSE(
      EvaluateTrajectory(options, reference, Trajectory(), &result, &error));
  EXPECT_EQ(error, "invalid option: delta = -2; it must be >= 1");
}

}  // namespace
}  // namespace mlndt
