// A coarse layer that ends at a rejected step below what it resolves
// (LayerScheduleOptions::coarse_rejected_step_cells) on the bundled koide3
// pair: fewer iterations for the same pose, within the reference's
// tolerance. The value is the one chosen on the simulator's train seeds
// (lab/records/rejected_steps.md).

#include <gtest/gtest.h>

#include <string>

#include "mlndt/common/pose.h"
#include "mlndt/registration/registration.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

RegistrationSummary Align(double coarse_rejected_step_cells) {
  static const PointCloud target =
      testing::LoadBundledCloud("koide3/251370668.pcd");
  static const PointCloud source =
      testing::LoadBundledCloud("koide3/251371071.pcd");
  RegistrationOptions options;
  options.schedule.coarse_rejected_step_cells = coarse_rejected_step_cells;
  RegistrationSummary summary;
  Register(options, target, source, Isometry3d::Identity(), &summary);
  return summary;
}

// Catches: the rule not reaching the backend (the same iterations), ending
// a coarse layer before its first taken steps (a far pose), or a rule that
// also ends the last layer on a rejected step (NO_CONVERGENCE or a pose off
// the converged one).
TEST(CoarseRejectedStep, FewerEvaluationsForTheSamePoseOnKoide3) {
  const RegistrationSummary off = Align(0.0);
  const RegistrationSummary on = Align(0.003);
  ASSERT_TRUE(off.IsSolutionUsable()) << off.message;
  ASSERT_TRUE(on.IsSolutionUsable()) << on.message;
  EXPECT_EQ(on.termination_type, off.termination_type);
  // koide3: 30 iterations by default, 26 (layers 1 and 3 end early).
  EXPECT_LE(on.num_iterations, off.num_iterations - 4);
  EXPECT_LT(on.point_iterations, off.point_iterations);
  // small_gicp's T_target_source: 5 cm and 0.5 deg (real_data_test.cc).
  Isometry3d expected;
  expected.matrix() << 0.999925, 0.0121483, -0.00177009, 0.488882,  //
      -0.0121523, 0.999924, -0.00228657, 0.121214,                  //
      0.00174218, 0.00230791, 0.999996, -0.0253342,                 //
      0, 0, 0, 1;
  EXPECT_LT(TranslationErrorM(expected, on.reference_from_input), 0.05);
  EXPECT_LT(RotationErrorRad(expected, on.reference_from_input) * kRadToDeg,
            0.5);
  // And the default's pose to a millimetre and a hundredth of a degree.
  EXPECT_LT(
      TranslationErrorM(off.reference_from_input, on.reference_from_input),
      1e-3);
  EXPECT_LT(
      RotationErrorRad(off.reference_from_input, on.reference_from_input) *
          kRadToDeg,
      0.01);
}

}  // namespace
}  // namespace mlndt
