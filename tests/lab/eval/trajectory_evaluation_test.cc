#include "lab/eval/trajectory_evaluation.h"

#include <gtest/gtest.h>

#include <fstream>

#include "mlndt/common/pose.h"
#include "tests/testing/scratch_dir.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

std::string Kitti(const std::string& name) {
  return testing::BundledDataPath("kitti/" + name);
}

EvaluationReference VeloReference() {
  EvaluationReference reference;
  reference.path = Kitti("poses_velo.txt");
  std::string error;
  EXPECT_TRUE(ReadEvaluationTrajectory(reference.path,
                                       true,
                                       TrajectoryFormat::KITTI,
                                       "",
                                       &reference.trajectory,
                                       &reference.format,
                                       &error))
      << error;
  return reference;
}

TrajectoryEvaluationOptions ShortSegments() {
  TrajectoryEvaluationOptions options;
  options.segments.lengths_m = {2.0, 4.0};
  options.segments.first_frame_step = 1;
  return options;
}

// The camera poses converted with calib.txt's Tr are the Velodyne poses:
// every error is rounding.
TEST(EvaluateTrajectory, CameraPosesConvertedWithTheCalibrationMatch) {
  const EvaluationReference reference = VeloReference();
  Trajectory cam;
  TrajectoryEvaluation result;
  result.file = Kitti("poses_cam0.txt");
  std::string error;
  ASSERT_TRUE(ReadEvaluationTrajectory(result.file,
                                       true,
                                       TrajectoryFormat::KITTI,
                                       Kitti("calib.txt"),
                                       &cam,
                                       &result.format,
                                       &error))
      << error;
  ASSERT_TRUE(
      EvaluateTrajectory(ShortSegments(), reference, cam, &result, &error))
      << error;
  EXPECT_EQ(result.association, "index");
  EXPECT_EQ(result.pairs, 8u);
  EXPECT_LT(result.ate.rmse_m, 1e-4);
  EXPECT_EQ(result.rpe_pairs, 7u);
  EXPECT_LT(result.rpe.translation_rmse_m, 1e-4);
  EXPECT_GT(result.path_length_m, 5.0);
  EXPECT_FALSE(result.kitti.lengths.empty());
}

// A drift of 1 % forward on every step shows in the RPE and the KITTI
// translation error, and the raw ATE without alignment is larger than
// after the SE3 fit.
TEST(EvaluateTrajectory, ScaledStepsShowInEveryMetric) {
  const EvaluationReference reference = VeloReference();
  const Trajectory& truth = reference.trajectory;
  Trajectory drifted;
  drifted.Add(0.0, truth.world_from_sensor(0));
  for (size_t k = 1; k < truth.size(); ++k) {
    Isometry3d step =
        truth.world_from_sensor(k - 1).inverse() * truth.world_from_sensor(k);
    step.translation() *= 1.01;
    drifted.Add(k, drifted.world_from_sensor(k - 1) * step);
  }
  std::string error;
  TrajectoryEvaluationOptions options = ShortSegments();
  options.alignment = TrajectoryAlignment::NONE;
  TrajectoryEvaluation raw;
  raw.file = "drifted";
  ASSERT_TRUE(EvaluateTrajectory(options, reference, drifted, &raw, &error))
      << error;
  // About 1 % (1.2 % here: the turns move the segment ends sideways too).
  EXPECT_GT(raw.kitti.translation_error_percent, 0.8);
  EXPECT_LT(raw.kitti.translation_error_percent, 1.5);
  EXPECT_GT(raw.rpe.translation_rmse_m, 1e-3);
  options.alignment = TrajectoryAlignment::SE3;
  TrajectoryEvaluation aligned;
  aligned.file = "drifted";
  ASSERT_TRUE(EvaluateTrajectory(options, reference, drifted, &aligned, &error))
      << error;
  EXPECT_LT(aligned.ate.rmse_m, raw.ate.rmse_m);
  EXPECT_GT(aligned.ate.rmse_m, 1e-3);
}

TEST(EvaluateTrajectory, TimestampAssociationNeedsStamps) {
  const EvaluationReference reference = VeloReference();  // KITTI: no stamps.
  TrajectoryEvaluationOptions options = ShortSegments();
  options.association = PoseAssociation::TIMESTAMP;
  TrajectoryEvaluation result;
  result.file = reference.path;
  std::string error;
  EXPECT_FALSE(EvaluateTrajectory(
      options, reference, reference.trajectory, &result, &error));
  EXPECT_NE(error.find("--association=timestamp needs stamps on both sides"),
            std::string::npos)
      << error;
}

TEST(CheckIndexPairing, RefusesDifferentLengthsUnlessIndexIsAsked) {
  const EvaluationReference reference = VeloReference();
  Trajectory shorter;
  for (size_t k = 0; k + 1 < reference.trajectory.size(); ++k) {
    shorter.Add(k, reference.trajectory.world_from_sensor(k));
  }
  TrajectoryEvaluationOptions options;
  std::string error;
  EXPECT_FALSE(CheckIndexPairing(options,
                                 reference,
                                 "short.txt",
                                 TrajectoryFormat::KITTI,
                                 shorter,
                                 &error));
  EXPECT_NE(error.find("short.txt has 7 poses, --reference 8"),
            std::string::npos)
      << error;
  options.association = PoseAssociation::INDEX;
  EXPECT_TRUE(CheckIndexPairing(options,
                                reference,
                                "short.txt",
                                TrajectoryFormat::KITTI,
                                shorter,
                                &error));
}

TEST(StampTrajectory, RefusesACountThatDiffers) {
  EvaluationReference reference = VeloReference();
  const std::string times = testing::ScratchPath("times.txt");
  {
    std::ofstream out(times);
    out << "0.0\n0.1\n0.2\n";
  }
  std::string error;
  EXPECT_FALSE(StampTrajectory(times, &reference.trajectory, &error));
  EXPECT_NE(error.find("has 3 stamps for 8 poses"), std::string::npos) << error;
}

TEST(PoseAssociation, StringsRoundTrip) {
  PoseAssociation association;
  for (const char* name : {"auto", "index", "timestamp"}) {
    ASSERT_TRUE(StringToPoseAssociation(name, &association)) << name;
    EXPECT_STREQ(PoseAssociationToString(association), name);
  }
  EXPECT_FALSE(StringToPoseAssociation("nearest", &association));
  // Lower case only, as the hand-written functions (from the table now).
  EXPECT_FALSE(StringToPoseAssociation("AUTO", &association));
  EXPECT_STREQ(PoseAssociationToString(static_cast<PoseAssociation>(9)),
               "unknown");
}

}  // namespace
}  // namespace mlndt
