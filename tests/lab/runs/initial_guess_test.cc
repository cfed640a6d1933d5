// Initial-guess policies: parsing, and the guess each policy gives.

#include "lab/runs/initial_guess.h"

#include <gtest/gtest.h>

#include "lab/eval/pose_error.h"
#include "mlndt/common/pose.h"

namespace mlndt {
namespace {

Isometry3d Motion(double tx, double yaw_deg) {
  return PoseVectorToIsometry(PoseVectorFromDegrees(tx, 0, 0, 0, 0, yaw_deg));
}

void ExpectSame(const Isometry3d& a, const Isometry3d& b) {
  EXPECT_TRUE(a.isApprox(b, 1e-12)) << a.matrix() << "\nvs\n" << b.matrix();
}

TEST(InitSpec, ParsesEveryPolicyAndPrintsItBack) {
  for (const std::string text : {"zero",
                                 "gt_fraction:0.6",
                                 "constant_velocity",
                                 "poses:/data/odometry.txt"}) {
    InitSpec spec;
    std::string error;
    ASSERT_TRUE(ParseInitSpec(text, &spec, &error)) << text << ": " << error;
    EXPECT_EQ(InitSpecToString(spec), text);
  }
  InitSpec spec;
  std::string error;
  ASSERT_TRUE(ParseInitSpec("gt_fraction:0.25", &spec, &error));
  EXPECT_EQ(spec.mode, InitMode::GT_FRACTION);
  EXPECT_EQ(spec.fraction, 0.25);
  ASSERT_TRUE(ParseInitSpec("poses:a.txt", &spec, &error));
  EXPECT_EQ(spec.mode, InitMode::POSES);
  EXPECT_EQ(spec.poses_path, "a.txt");
}

TEST(InitSpec, RejectsMalformedText) {
  for (const std::string text : {"",
                                 "identity",
                                 "gt_fraction:",
                                 "gt_fraction:x",
                                 "gt_fraction:0.5,0.6",
                                 "gt_fraction:inf",
                                 "poses:"}) {
    InitSpec spec;
    std::string error;
    EXPECT_FALSE(ParseInitSpec(text, &spec, &error)) << text;
    EXPECT_NE(error.find("--init=" + text), std::string::npos) << error;
  }
}

TEST(InitialGuessPolicy, ZeroIsTheIdentity) {
  InitialGuessPolicy policy(InitSpec{});
  ExpectSame(policy.Guess(Motion(1, 5), Motion(2, 3)), Isometry3d::Identity());
}

TEST(InitialGuessPolicy, GtFractionScalesTheTruth) {
  InitSpec spec;
  spec.mode = InitMode::GT_FRACTION;
  spec.fraction = 0.5;
  InitialGuessPolicy policy(spec);
  const Isometry3d truth = Motion(2, 10);
  ExpectSame(policy.Guess(truth, Motion(7, 7)), ScaleMotion(truth, 0.5));
  ExpectSame(policy.Guess(truth, Motion(7, 7)), Motion(1, 5));
}

TEST(InitialGuessPolicy, PosesUseTheOdometry) {
  InitSpec spec;
  spec.mode = InitMode::POSES;
  InitialGuessPolicy policy(spec);
  ExpectSame(policy.Guess(Motion(1, 1), Motion(2, 3)), Motion(2, 3));
}

TEST(InitialGuessPolicy, ConstantVelocityUsesThePreviousUsableEstimate) {
  InitSpec spec;
  spec.mode = InitMode::CONSTANT_VELOCITY;
  InitialGuessPolicy policy(spec);
  const Isometry3d truth = Motion(5, 5);
  ExpectSame(policy.Guess(truth, truth), Isometry3d::Identity());  // First.
  policy.Record(true, Motion(1, 2));
  ExpectSame(policy.Guess(truth, truth), Motion(1, 2));
  policy.Record(false, Motion(9, 9));  // Not usable: ignored.
  ExpectSame(policy.Guess(truth, truth), Motion(1, 2));
  policy.Record(true, Motion(3, 4));
  ExpectSame(policy.Guess(truth, truth), Motion(3, 4));
}

}  // namespace
}  // namespace mlndt
