// Rival minima (rival_minima.h): when two minima are distinct, which one
// rivals the result, that a fit is scored only for distinct minima, and the
// starts around a centre.

#include "mlndt/registration/rival_minima.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

#include "mlndt/common/pose.h"

namespace mlndt {
namespace {

Isometry3d Pose(double x_m, double yaw_deg) {
  return PoseVectorToIsometry(
      PoseVectorFromDegrees(x_m, 0.0, 0.0, 0.0, 0.0, yaw_deg));
}

TEST(DistinctMinima, SeparateBoundsOrOneDistanceWithALever) {
  MinimaSeparation bounds;  // Half a 1 m cell, or 5 deg.
  bounds.max_rotation_deg = 5.0;
  EXPECT_FALSE(DistinctMinima(bounds, Pose(0.0, 0.0), Pose(0.4, 4.0)));
  EXPECT_TRUE(DistinctMinima(bounds, Pose(0.0, 0.0), Pose(0.6, 0.0)));
  EXPECT_TRUE(DistinctMinima(bounds, Pose(0.0, 0.0), Pose(0.0, 6.0)));
  // With a 10 m lever 2 deg moves a point 0.35 m: with 0.2 m, 0.55 > 0.5.
  MinimaSeparation lever;
  lever.lever_m = 10.0;
  EXPECT_FALSE(DistinctMinima(lever, Pose(0.0, 0.0), Pose(0.2, 1.0)));
  EXPECT_TRUE(DistinctMinima(lever, Pose(0.0, 0.0), Pose(0.2, 2.0)));
}

TEST(FindRivalMinimum, TheFirstDistinctMinimumNotClearlyWorse) {
  RivalMinimaOptions options;
  options.as_well_margin = 0.02;
  // The result (0), one in its basin, one clearly worse, two as good.
  const std::vector<Isometry3d> minima = {Pose(0.0, 0.0),
                                          Pose(0.1, 0.0),
                                          Pose(2.0, 0.0),
                                          Pose(3.0, 0.0),
                                          Pose(4.0, 0.0)};
  const std::vector<double> fits = {0.90, 0.99, 0.80, 0.885, 0.95};
  std::vector<size_t> asked;
  const RivalMinimaSummary rival =
      FindRivalMinimum(options, minima, 0, [&](size_t i) {
        asked.push_back(i);
        return fits[i];
      });
  ASSERT_TRUE(rival.found());
  EXPECT_EQ(rival.rival, 3);
  EXPECT_DOUBLE_EQ(rival.apart_m, 3.0);
  // The minimum in the result's basin is not scored, the last not reached.
  EXPECT_EQ(asked, (std::vector<size_t>{0, 2, 3}));

  options.as_well_margin = 0.0;  // Now only 4 fits as well.
  EXPECT_EQ(
      FindRivalMinimum(options, minima, 0, [&](size_t i) { return fits[i]; })
          .rival,
      4);
}

TEST(FindRivalMinimum, AnInfiniteMarginMakesEveryDistinctMinimumARival) {
  RivalMinimaOptions options;
  options.as_well_margin = std::numeric_limits<double>::infinity();
  const auto worse = [](size_t i) { return i == 0 ? 1.0 : -1e9; };
  EXPECT_FALSE(
      FindRivalMinimum(options, {Pose(0, 0), Pose(0.3, 0)}, 0, worse).found());
  EXPECT_TRUE(
      FindRivalMinimum(options, {Pose(0, 0), Pose(0.7, 0)}, 0, worse).found());
  std::string error;
  EXPECT_TRUE(options.IsValid(&error)) << error;
  options.separation.cell_size_m = 0.0;
  EXPECT_FALSE(options.IsValid(&error));
}

TEST(StartsAround, BothWaysAlongXYThenTurned) {
  const Isometry3d centre = Pose(1.0, 90.0);
  const std::vector<Isometry3d> starts = StartsAround(centre, 0.5, 10.0);
  ASSERT_EQ(starts.size(), 6u);
  // +x in the centre's frame (turned 90 deg) is +y in the world's.
  EXPECT_NEAR(starts[0].translation().y(), 0.5, 1e-12);
  EXPECT_NEAR(starts[2].translation().y(), -0.5, 1e-12);
  EXPECT_NEAR(RotationErrorRad(centre, starts[4]) * kRadToDeg, 10.0, 1e-9);
  EXPECT_EQ(StartsAround(centre, 0.0, 10.0).size(), 2u);
  EXPECT_TRUE(StartsAround(centre, 0.0, 0.0).empty());
}

}  // namespace
}  // namespace mlndt
