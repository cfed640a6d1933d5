#include "lab/eval/pose_error.h"

#include <gtest/gtest.h>

#include <cmath>

#include "mlndt/common/pose.h"
#include "tests/testing/eigen_near.h"

namespace mlndt {
namespace {

using testing::EigenNear;

PoseError ErrorOf(double translation_m, double rotation_deg) {
  PoseError e;
  e.translation_m = translation_m;
  e.rotation_rad = rotation_deg * kDegToRad;
  return e;
}

TEST(ComputePoseError, IsTheTruthInverseTimesTheEstimate) {
  // A truth with a large rotation, so that truth^-1 * estimate and
  // estimate * truth^-1 differ.
  const Isometry3d truth =
      PoseVectorToIsometry(PoseVectorFromDegrees(3, -1, 2, 10, -20, 70));
  const Vector6d delta_xi = PoseVectorFromDegrees(0.3, 0.1, -0.2, 1, -2, 3);
  const Isometry3d estimate = truth * PoseVectorToIsometry(delta_xi);
  const PoseError e = ComputePoseError(truth, estimate);
  EXPECT_TRUE(EigenNear(e.components, delta_xi, 1e-12));
  EXPECT_NEAR(e.translation_m, delta_xi.head<3>().norm(), 1e-12);
  EXPECT_NEAR(e.translation_m, TranslationErrorM(truth, estimate), 1e-12);
  EXPECT_NEAR(e.rotation_rad, RotationErrorRad(truth, estimate), 1e-12);
  EXPECT_NEAR(e.rotation_deg(), e.rotation_rad * kRadToDeg, 1e-12);
  EXPECT_GT(e.rotation_deg(), 3.0);  // The three angles combine.
}

TEST(ComputePoseError, ZeroForTheTruthItself) {
  const Isometry3d truth =
      PoseVectorToIsometry(PoseVectorFromDegrees(1, 2, 3, 4, 5, 6));
  const PoseError e = ComputePoseError(truth, truth);
  EXPECT_NEAR(e.translation_m, 0.0, 1e-12);
  EXPECT_NEAR(e.rotation_rad, 0.0, 1e-7);
  EXPECT_TRUE(EigenNear(e.components, Vector6d::Zero(), 1e-7));
}

TEST(SuccessCriterion, DefaultIsStrictlyBelowTwentyCentimetresAndOneDegree) {
  const SuccessCriterion strict;
  EXPECT_EQ(strict.max_translation_m, 0.2);
  EXPECT_EQ(strict.max_rotation_deg, 1.0);
  EXPECT_TRUE(strict.IsWithin(ErrorOf(0.19, 0.99)));
  EXPECT_FALSE(strict.IsWithin(ErrorOf(0.2, 0.5)));   // Limit excluded.
  EXPECT_FALSE(strict.IsWithin(ErrorOf(0.1, 1.0)));   // Limit excluded.
  EXPECT_FALSE(strict.IsWithin(ErrorOf(0.1, 1.01)));  // Rotation counts.
}

TEST(SuccessCriterion, PaperRuleChecksOnlyTheTranslation) {
  EXPECT_EQ(kPaperSuccessCriterion.max_translation_m, 0.5);
  EXPECT_TRUE(kPaperSuccessCriterion.IsWithin(ErrorOf(0.49, 30.0)));
  EXPECT_FALSE(kPaperSuccessCriterion.IsWithin(ErrorOf(0.5, 0.0)));
}

TEST(ScaleMotion, ScalesTranslationAndRotationAngleAboutTheSameAxis) {
  const Vector3d axis = Vector3d(1, 2, -1).normalized();
  Isometry3d motion = Isometry3d::Identity();
  motion.linear() = Eigen::AngleAxisd(0.6, axis).toRotationMatrix();
  motion.translation() = Vector3d(2, -4, 1);
  const Isometry3d half = ScaleMotion(motion, 0.5);
  const Eigen::AngleAxisd half_rotation(half.linear());
  EXPECT_NEAR(half_rotation.angle(), 0.3, 1e-12);
  EXPECT_TRUE(EigenNear(half_rotation.axis(), axis, 1e-12));
  EXPECT_TRUE(EigenNear(half.translation(), Vector3d(1, -2, 0.5), 1e-12));
  // Twice half a motion is the motion (same axis, so the rotations add).
  EXPECT_TRUE(EigenNear((half * half).linear(), motion.linear(), 1e-12));
  EXPECT_TRUE(ScaleMotion(motion, 0.0).isApprox(Isometry3d::Identity()));
  EXPECT_TRUE(ScaleMotion(motion, 1.0).isApprox(motion, 1e-12));
}

}  // namespace
}  // namespace mlndt
