// The prior along the directions the data leave free
// (registration/internal/prior_hold.h), on scenes whose free directions are
// known. A finite corridor's axis (and the roll about it) is free (its ends are
// a few cells among thousands), yet its ends pull an input that overhangs them
// back into the reference: without the rule the pose slides along the axis,
// away from the guess, by how much the ends overhang. With a prior the pose
// keeps the guess's value along the axis and converges on the rest, and the
// covariance along the axis is the prior's. Without a prior nothing
// changes: the axis is unbounded in the covariance. On a street scene, which
// constrains every direction, the prior holds nothing.

#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>

#include "mlndt/common/pose.h"
#include "mlndt/registration/registration.h"
#include "tests/testing/synthetic_scene.h"

namespace mlndt {
namespace {

Isometry3d Pose(const Eigen::Vector3d& t, double yaw_deg) {
  Isometry3d pose = Isometry3d::Identity();
  pose.linear() =
      Eigen::AngleAxisd(yaw_deg * kDegToRad, Eigen::Vector3d::UnitZ())
          .toRotationMatrix();
  pose.translation() = t;
  return pose;
}

// The truth, and a guess 0.3 m off along the free axis, 5 cm and 4 cm
// across it and 1 deg in yaw.
const Isometry3d kTruth = Pose({1.0, 0.2, 0.0}, 0.0);
const Isometry3d kGuess = Pose({1.3, 0.25, -0.04}, 1.0);

RegistrationSummary RegisterCorridor(const RegistrationOptions& options) {
  RegistrationSummary summary;
  Register(options,
           testing::SlabCorridor(1),
           TransformCloud(kTruth.inverse(), testing::SlabCorridor(2)),
           kGuess,
           &summary);
  return summary;
}

RegistrationOptions WithPrior(double translation_m, double rotation_deg) {
  RegistrationOptions options;
  options.initial_uncertainty.given = true;
  options.initial_uncertainty.translation_m = translation_m;
  options.initial_uncertainty.rotation_deg = rotation_deg;
  return options;
}

TEST(PriorHold, KeepsTheGuessAlongTheFreeAxisAndConvergesAcrossIt) {
  const RegistrationSummary s = RegisterCorridor(WithPrior(0.5, 3.0));
  const Isometry3d& x = s.reference_from_input;
  EXPECT_EQ(s.termination_type, TerminationType::DEGENERATE) << s.message;
  EXPECT_GE(s.prior_held_directions, 1) << s.FullReport();
  // Along the axis: the guess's value (the ends would pull it 0.3 m back).
  EXPECT_NEAR(x.translation().x(), kGuess.translation().x(), 0.01)
      << s.FullReport();
  // Across it: the truth.
  EXPECT_NEAR(x.translation().y(), kTruth.translation().y(), 0.01);
  EXPECT_NEAR(x.translation().z(), kTruth.translation().z(), 0.01);
  EXPECT_LT(RotationErrorRad(x, kTruth), 0.1 * kDegToRad) << s.FullReport();
  // The covariance: the prior's along the axis (0.5 m as one standard
  // deviation) and about it (the roll, free too: 3 deg), the data's on
  // the height and the yaw.
  const double prior_roll_rad = 3.0 * kDegToRad;
  EXPECT_NEAR(s.covariance(0, 0), 0.25, 0.05) << s.FullReport();
  EXPECT_NEAR(s.covariance(3, 3),
              prior_roll_rad * prior_roll_rad,
              0.2 * prior_roll_rad * prior_roll_rad)
      << s.FullReport();
  EXPECT_LT(s.covariance(2, 2), 1e-4) << s.FullReport();
  EXPECT_LT(s.covariance(5, 5), 1e-6) << s.FullReport();
  EXPECT_NE(s.message.find("keeps the prior's value"), std::string::npos)
      << s.message;
}

// The rule's effect is not a coincidence of the objective: without a
// prior the ends pull the pose along the axis, away from the guess, and
// the covariance leaves the axis unbounded.
TEST(PriorHold, WithoutAPriorNothingIsHeld) {
  const RegistrationSummary s = RegisterCorridor(RegistrationOptions());
  EXPECT_EQ(s.termination_type, TerminationType::DEGENERATE) << s.message;
  EXPECT_EQ(s.prior_held_directions, 0);
  EXPECT_TRUE(std::isinf(s.covariance(0, 0))) << s.FullReport();
  EXPECT_GT(std::abs(s.reference_from_input.translation().x() -
                     kGuess.translation().x()),
            0.1)
      << s.FullReport();
}

// A scene that constrains every direction: the prior holds nothing, and
// the result is the truth.
TEST(PriorHold, HoldsNothingWhereTheSceneConstrainsThePose) {
  const Isometry3d truth = Pose({0.4, -0.2, 0.05}, 3.0);
  RegistrationSummary s;
  Register(
      WithPrior(0.5, 5.0),
      testing::StreetScene(60000, 0.01, 1),
      TransformCloud(truth.inverse(), testing::StreetScene(20000, 0.01, 2)),
      Pose({0.5, -0.1, 0.0}, 1.0),
      &s);
  EXPECT_EQ(s.termination_type, TerminationType::CONVERGENCE) << s.message;
  EXPECT_EQ(s.prior_held_directions, 0);
  EXPECT_LT(TranslationErrorM(s.reference_from_input, truth), 0.02);
  EXPECT_LT(RotationErrorRad(s.reference_from_input, truth), 0.1 * kDegToRad);
}

}  // namespace
}  // namespace mlndt
