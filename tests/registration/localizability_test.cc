// The translation's localizability (localizability.h) on scenes whose free
// directions are known: a corridor leaves its axis to no normal at any
// density, a street scene constrains every translation.

#include "mlndt/registration/localizability.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "mlndt/cloud/point_cloud.h"
#include "mlndt/common/pose.h"
#include "mlndt/cost/objective_options.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/registration/internal/unlocalizable_directions.h"
#include "mlndt/registration/quality_check.h"
#include "mlndt/registration/registration.h"
#include "tests/testing/synthetic_scene.h"

namespace mlndt {
namespace {

// The share QualityCheckOptions::min_localizability was chosen at on the
// simulator's training seeds (0-3; docs/trust.md).
constexpr double kTrainedMinLocalizability = 0.02;

// The matches of `input` at the identity on the last layer of *map, built
// from `reference` (the default map; the matches point into it).
std::vector<PointMatch> MatchesAtIdentity(const PointCloud& reference,
                                          const PointCloud& input,
                                          LayeredGrid* map) {
  std::string error;
  EXPECT_TRUE(LayeredGrid::Build(LayeredGridOptions(), reference, map, &error))
      << error;
  return MatchPoints(map->layer(map->num_layers()),
                     input.points(),
                     Matrix3d::Identity(),
                     Eigen::Vector3d::Zero(),
                     ObjectiveOptions().unmatched_policy);
}

// The localizability of `input` at the identity on `reference`'s last
// layer (the default map), inliers as the quality check's gate.
Localizability AtIdentity(const PointCloud& reference,
                          const PointCloud& input) {
  LayeredGrid map;
  return LocalizabilityOf(MatchesAtIdentity(reference, input, &map),
                          QualityCheckOptions().inlier_gate);
}

// The share of the direction closest to `axis`.
double ShareAlong(const Localizability& l, const Eigen::Vector3d& axis) {
  Eigen::Index k = 0;
  (l.directions.transpose() * axis).cwiseAbs().maxCoeff(&k);
  return l.share(k);
}

class CorridorLocalizability : public ::testing::TestWithParam<int> {};

// Almost no normal of the walls or the floor leans on the axis (only the
// sampling noise of sparse cells): its share is below 1 % at 8000 and at
// 45000 points, the two across it are constrained by a wall or
// the floor each.
TEST_P(CorridorLocalizability, NoPointConstrainsTheAxisAtAnyDensity) {
  const int n = GetParam();
  const Localizability l = AtIdentity(testing::Corridor(50.0, n * 5 / 2, 1),
                                      testing::Corridor(20.0, n, 2));
  ASSERT_GT(l.planar_points, n / 2);
  EXPECT_GT(std::abs(l.directions.col(0).x()), 0.99) << l.directions;
  EXPECT_LT(ShareAlong(l, Eigen::Vector3d::UnitX()), 0.01) << l.share;
  EXPECT_GT(ShareAlong(l, Eigen::Vector3d::UnitY()), 0.3) << l.share;
  EXPECT_GT(ShareAlong(l, Eigen::Vector3d::UnitZ()), 0.3) << l.share;
  EXPECT_LT(l.share.minCoeff(), kTrainedMinLocalizability);
}

INSTANTIATE_TEST_SUITE_P(Localizability,
                         CorridorLocalizability,
                         ::testing::Values(8000, 45000));

// The street's cross walls, boxes and poles face along it: every
// translation is constrained by more than the quality check asks.
TEST(Localizability, AStreetConstrainsEveryTranslation) {
  const Localizability l = AtIdentity(testing::StreetScene(60000, 0.01, 1),
                                      testing::StreetScene(20000, 0.01, 2));
  ASSERT_GT(l.planar_points, 5000);
  EXPECT_GT(l.share.minCoeff(), kTrainedMinLocalizability) << l.share;
  EXPECT_NEAR(l.information.sum(), 1.0, 1e-9);
}

// With the probe of weak directions and the constraint ratio off, the
// localizability alone makes a
// sparse corridor DEGENERATE along its axis, with an unbounded covariance
// there and a bounded one across it.
TEST(Localizability, MakesACorridorDegenerateWithoutTheProbe) {
  RegistrationOptions options;
  options.quality_check.min_localizability = kTrainedMinLocalizability;
  options.quality_check.max_flatness = 1.0;          // The probe off.
  options.quality_check.min_constraint_ratio = 0.0;  // The ratio off.
  Isometry3d truth = Isometry3d::Identity();
  truth.translation() = Eigen::Vector3d(1.0, 0.1, 0.0);
  RegistrationSummary s;
  Register(options,
           testing::Corridor(50.0, 20000, 1),
           TransformCloud(truth.inverse(), testing::Corridor(20.0, 8000, 2)),
           Isometry3d::Identity(),
           &s);
  EXPECT_EQ(s.termination_type, TerminationType::DEGENERATE) << s.message;
  EXPECT_GE(s.constraints.unlocalizable_directions, 1) << s.message;
  EXPECT_NE(s.message.find("translation along (1.00, "), std::string::npos)
      << s.message;
  EXPECT_GE(s.covariance(0, 0), 1.0) << s.FullReport();
  EXPECT_LT(s.covariance(1, 1), 0.01) << s.FullReport();
}

// The verdict and the prior hold name a corridor's axis through one
// function: added once with its share, and not again when another test
// (the probe, the ratio) already named it.
TEST(Localizability, TheUnlocalizableAxisIsNamedOnce) {
  LayeredGrid map;
  const std::vector<PointMatch> matches =
      MatchesAtIdentity(testing::Corridor(50.0, 20000, 1),
                        testing::Corridor(20.0, 8000, 2),
                        &map);
  QualityCheckOptions options;
  options.min_localizability = kTrainedMinLocalizability;
  ConstraintAnalysis analysis;
  const std::vector<Vector6d> added =
      internal::AddUnlocalizableDirections(matches, options, &analysis);
  ASSERT_EQ(added.size(), 1u);
  EXPECT_GT(std::abs(added[0].x()), 0.99) << added[0].transpose();
  EXPECT_EQ(analysis.unlocalizable_directions, 1);
  ASSERT_EQ(analysis.degenerate_directions.size(), 1u);
  EXPECT_LT(analysis.localizability, kTrainedMinLocalizability);
  EXPECT_GT(std::abs(analysis.least_localizable_direction.x()), 0.99);

  ConstraintAnalysis probed;  // The axis named by the probe, 10 deg off.
  Vector6d axis = Vector6d::Zero();
  axis.head<3>() = Eigen::Vector3d(std::cos(0.17), std::sin(0.17), 0.0);
  probed.degenerate_directions.push_back(axis);
  EXPECT_TRUE(
      internal::AddUnlocalizableDirections(matches, options, &probed).empty());
  EXPECT_EQ(probed.unlocalizable_directions, 0);
  EXPECT_EQ(probed.degenerate_directions.size(), 1u);
  EXPECT_LT(probed.localizability, kTrainedMinLocalizability);
}

// Nothing on planar cells: empty.
TEST(Localizability, NoMatchesIsEmpty) {
  const Localizability l = LocalizabilityOf({}, 3.0);
  EXPECT_EQ(l.planar_points, 0);
  EXPECT_EQ(l.share, Eigen::Vector3d::Zero());
}

}  // namespace
}  // namespace mlndt
