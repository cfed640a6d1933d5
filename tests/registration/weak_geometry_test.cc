// Issue 22's weak-geometry inputs made from the bundled KITTI frames 0-7
// (scripts/make_kitti_crops.py makes the same crops for mlndt_suite): the
// whole reference scan i, the input scan i+1 cropped to points within 8 m,
// or thinned to every 200th point. From the identity (0.7 m behind) the
// near crop's along-track translation is weakly determined, and before the
// probe of weak directions every one of these results stayed at the start
// and was reported CONVERGENCE; the thinned input keeps ~150 sampled points.
// With the probe at max_flatness 0.8 (opt-in: it also flags right results
// on sparse synthetic streets and KITTI crops, docs/trust.md) and the
// 500-point floor (on by default), a result reported CONVERGENCE is right.
// The default probe (0.95) keeps right results and does not flag the near
// crop: its wrong poses keep 0.78-0.92 of the inliers one cell away, as
// right ones do. The search along the flattest weak direction
// (RetryOptions::weak_direction_rounds) finds the better minimum along the
// road for most of them (issue 22).

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "lab/eval/reference_pairs.h"
#include "mlndt/cloud/io.h"
#include "mlndt/common/pose.h"
#include "mlndt/registration/registration.h"
#include "tests/testing/kitti_bundle.h"
#include "tests/testing/shared_pair.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

PointCloud Crop(const PointCloud& cloud,
                const std::function<bool(int, const Eigen::Vector3d&)>& keep) {
  PointCloud kept;
  for (size_t k = 0; k < cloud.size(); ++k) {
    if (keep(static_cast<int>(k), cloud.points()[k])) {
      kept.Add(cloud.points()[k]);
    }
  }
  return kept;
}

struct Tally {
  int converged_right = 0;
  int converged_wrong = 0;
  int right = 0;  // Whatever the verdict.
  std::string report;
};

// The near crop: the input's points within 8 m of its sensor.
bool WithinEightMetres(int, const Eigen::Vector3d& p) {
  return p.norm() <= 8.0;
}

using FramePairs = std::vector<std::pair<int, int>>;

// Where each registration starts: the identity (0.7 m behind), or the
// data set's prior (odometry, 8-18 cm off).
enum class Start { kIdentity, kPrior };

const FramePairs kConsecutive = {
    {0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 6}, {6, 7}};

// Registers the cropped input of each pair (reference frame, input frame;
// consecutive by default) from `start` and tallies the results against the
// bundled consensus references.
Tally RegisterCrops(
    const std::function<bool(int, const Eigen::Vector3d&)>& keep,
    const RegistrationOptions& options = RegistrationOptions(),
    const FramePairs& frame_pairs = kConsecutive,
    Start start = Start::kIdentity) {
  std::map<std::string, ReferencePair> pairs;
  std::string error;
  EXPECT_TRUE(ReadReferencePairs(
      testing::BundledDataPath("kitti/reference_pairs.json"), &pairs, &error))
      << error;
  Tally tally;
  for (const auto& [i, j] : frame_pairs) {
    const ReferencePair& pair = pairs.at(ReferencePairKey(i, j));
    const Isometry3d& truth = pair.reference_from_input;
    RegistrationSummary s;
    Register(options,
             testing::BundledKittiScan(i),
             Crop(testing::BundledKittiScan(j), keep),
             start == Start::kPrior ? pair.prior_from_input.value()
                                    : Isometry3d::Identity(),
             &s);
    const double error_m = TranslationErrorM(truth, s.reference_from_input);
    const bool right =
        error_m < 0.2 &&
        RotationErrorRad(truth, s.reference_from_input) < 1.0 * kDegToRad;
    tally.right += right;
    if (s.termination_type == TerminationType::CONVERGENCE) {
      (right ? tally.converged_right : tally.converged_wrong)++;
    }
    tally.report += ReferencePairKey(i, j) + ": " + std::to_string(error_m) +
                    " m, " + s.message + "\n";
  }
  return tally;
}

// The verdict without the localizability test (step 6 of
// registration/internal/attempts.h), which flags most of these crops' wrong
// minima on its own: the counterfactuals below measure what one search or
// check does, so they leave it out.
RegistrationOptions WithoutLocalizability(RegistrationOptions options) {
  options.quality_check.min_localizability = 0.0;
  return options;
}

TEST(WeakGeometry, InputWithinEightMetresIsNeverWronglyConvergedWithTheProbe) {
  RegistrationOptions probed;
  probed.quality_check.max_flatness = 0.8;
  const Tally tally = RegisterCrops(WithinEightMetres, probed);
  EXPECT_EQ(tally.converged_wrong, 0) << tally.report;
  // Without the search along the weak direction (and the scan-pattern
  // check, which finds the same minima), the default probe (0.95) lets the
  // same results stay at the identity, wrong and called CONVERGENCE: the 0.8
  // setting is what flags them.
  RegistrationOptions no_search;
  no_search.retry.weak_direction_rounds = 0;
  no_search.retry.scan_pattern_reach_cells = 0.0;
  EXPECT_GE(RegisterCrops(WithinEightMetres, WithoutLocalizability(no_search))
                .converged_wrong,
            5);
  // The localizability test alone flags them: under 2 % of the inliers on
  // planar cells (the road, the kerbs) constrain the road's direction.
  EXPECT_EQ(RegisterCrops(WithinEightMetres, no_search).converged_wrong, 0);
}

TEST(WeakGeometry, TheSearchAlongTheRoadLeavesTheIdentityForTheBetterMinimum) {
  RegistrationOptions no_search;  // Nor the scan-pattern check.
  no_search.retry.weak_direction_rounds = 0;
  no_search.retry.scan_pattern_reach_cells = 0.0;
  const Tally before =
      RegisterCrops(WithinEightMetres, WithoutLocalizability(no_search));
  EXPECT_EQ(before.converged_right, 0) << before.report;
  // The default searches one cell edge along the flattest weak direction
  // (the road) both ways and keeps a minimum that has clearly more inliers.
  const Tally after =
      RegisterCrops(WithinEightMetres, WithoutLocalizability({}));
  EXPECT_GE(after.converged_right, 4) << after.report;
  EXPECT_LT(after.converged_wrong, before.converged_wrong) << after.report;
}

// Hand-held Livox Avia scans (shared data): from the identity (0.3-0.7 m and
// 12-16 deg from the reference) these pairs ended in a minimum 1.1 m
// (185->188) and 0.25 m (186->188) off that passes the fit check; the search
// along the flattest weak direction finds the right one, which has clearly
// more inliers.
TEST(WeakGeometry, LivoxPairsFromTheIdentityEndInTheBetterMinimum) {
  MLNDT_REQUIRE_SHARED_DATA(dir);
  for (const char* key : {"185_188", "186_188"}) {
    const testing::SharedPair shared =
        testing::ReadSharedPair(dir + "/fastlio_avia_hku_2_pairs", key);
    const ReferencePair& pair = shared.pair;
    const PointCloud& reference = shared.reference;
    const PointCloud& input = shared.input;
    RegistrationOptions no_search;
    no_search.retry.weak_direction_rounds = 0;
    for (const bool search : {false, true}) {
      RegistrationSummary s;
      Register(search ? RegistrationOptions() : no_search,
               reference,
               input,
               Isometry3d::Identity(),
               &s);
      ASSERT_EQ(s.termination_type, TerminationType::CONVERGENCE)
          << key << ": " << s.message;
      const double error_m =
          TranslationErrorM(pair.reference_from_input, s.reference_from_input);
      // The references are the LIO prior, good to about 2-5 cm.
      if (search) {
        EXPECT_LT(error_m, 0.06) << key;
      } else {
        EXPECT_GT(error_m, 0.2) << key;  // What the search corrects.
      }
    }
  }
}

// The input cropped to the ground (z < -1.4 m; the sensor is 1.73 m up).
// Beyond a few metres a ring crosses each ground cell alone, and from the
// identity the input's rings fall into the cells of the reference's own
// rings: without the scan-pattern check (RetryOptions::
// scan_pattern_reach_cells) three results stayed there, 0.7 m behind, and
// were reported CONVERGENCE. 1->2 stayed there with the check too, from the
// identity and from the prior (16 cm off): the planar cells alone lead only
// 9 cm from it, and the minimum beyond it, 0.7 m ahead, has fewer inliers
// on the last layer (z = -3.8) but clearly more on the planar cells
// (z = 12.5): the rings and the scene disagree, and the result is flagged.
TEST(WeakGeometry, AGroundOnlyInputIsNotHeldWhereTheSensorsCoincide) {
  const auto ground = [](int, const Eigen::Vector3d& p) {
    return p.z() < -1.4;
  };
  RegistrationOptions unchecked = WithoutLocalizability({});
  unchecked.retry.scan_pattern_reach_cells = 0.0;
  const Tally before = RegisterCrops(ground, unchecked);
  EXPECT_GE(before.converged_wrong, 3) << before.report;
  const Tally after = RegisterCrops(ground);
  EXPECT_EQ(after.converged_wrong, 0) << after.report;
  EXPECT_GE(after.converged_right, before.converged_right) << after.report;
  const Tally from_prior =
      RegisterCrops(ground, RegistrationOptions(), {{1, 2}}, Start::kPrior);
  EXPECT_EQ(from_prior.converged_wrong, 0) << from_prior.report;
}

// The input cropped to a +-15 deg wedge ahead: the road and what lies
// beyond it. Where the sensors coincide the rings fit the last layer better
// than the right pose, 0.7-0.8 m ahead (6->7: 37 % of the points inliers
// against 31 %), and the coarse layers carry the prior (9 cm off) there too;
// the planar cells hold clearly more inliers at the right pose (z = 3-6).
// Without that comparison 3->4 (from the identity) and 6->7 (from both
// starts) were reported CONVERGENCE where the sensors coincide; with it,
// they end at the right pose and say that the fit is poor (LOW_QUALITY).
// 3->4 is looked beyond only since the gate asks the planar cells along the
// road (73 % of their inliers kept one cell away) rather than the flattest
// direction (54 %, under the search's 60 %).
TEST(WeakGeometry, AWedgeAheadIsNotHeldWhereTheSensorsCoincide) {
  const auto wedge = [](int, const Eigen::Vector3d& p) {
    return std::abs(std::atan2(p.y(), p.x())) <= 15.0 * kDegToRad;
  };
  const Tally identity =
      RegisterCrops(wedge, RegistrationOptions(), {{3, 4}, {6, 7}});
  EXPECT_EQ(identity.converged_wrong, 0) << identity.report;
  EXPECT_EQ(identity.right, 2) << identity.report;
  const Tally prior =
      RegisterCrops(wedge, RegistrationOptions(), {{6, 7}}, Start::kPrior);
  EXPECT_EQ(prior.converged_wrong, 0) << prior.report;
  EXPECT_EQ(prior.right, 1) << prior.report;
}

// The input cropped to 8 m, one and two frames from the reference
// (0.7-1.5 m ahead). From the identity the rings held these six results
// where the sensors coincide, wrong: the planar cells there hold two rings
// each and keep the same minimum, and the search along the flattest weak
// direction (a mix of the road and the turn) led to worse minima. Four were
// reported CONVERGENCE; 0->1 and 1->3 are DEGENERATE only because the
// search's minima ahead fit about as well. The scan-pattern check also runs
// the last layer from the result moved 1.5 cell edges along the translation
// the planar cells constrain least, both ways, and the scene's own minimum
// ahead has more inliers. For 0->1 it has only a few more (z = 0.77): the
// minimum where the sensors coincide fits about as well, and the right pose
// it reaches is DEGENERATE.
TEST(WeakGeometry, TheNearCropsMinimumBeyondTheRingsIsFound) {
  const FramePairs ahead = {{0, 1}, {1, 3}, {2, 4}, {3, 5}, {5, 7}, {6, 7}};
  RegistrationOptions unchecked = WithoutLocalizability({});
  unchecked.retry.scan_pattern_reach_cells = 0.0;
  const Tally before = RegisterCrops(WithinEightMetres, unchecked, ahead);
  EXPECT_EQ(before.right, 0) << before.report;
  EXPECT_EQ(before.converged_wrong, 4) << before.report;
  const Tally after =
      RegisterCrops(WithinEightMetres, RegistrationOptions(), ahead);
  EXPECT_EQ(after.right, 6) << after.report;
  EXPECT_EQ(after.converged_right, 5) << after.report;
}

// The input cropped to 8 m, 1->2 from the identity (0.70 m behind): where
// the sensors coincide and at the right pose, 0.63 m ahead, 91 % and 90 %
// of the points are inliers, and the planar cells prefer the former
// (z = -2.6), which was reported CONVERGENCE with a 9 mm sigma along the
// road. The data do not decide between the two: DEGENERATE, with the road
// named and unbounded.
// The localizability test (on by default) already says so: no inlier on a
// planar cell constrains the road's direction.
TEST(WeakGeometry, TwoMinimaThatFitAsWellAreDegenerate) {
  for (const bool localizability : {false, true}) {
    RegistrationSummary s;
    Register(localizability ? RegistrationOptions() : WithoutLocalizability({}),
             testing::BundledKittiScan(1),
             Crop(testing::BundledKittiScan(2), WithinEightMetres),
             Isometry3d::Identity(),
             &s);
    EXPECT_EQ(s.termination_type, TerminationType::DEGENERATE) << s.message;
    EXPECT_NE(s.message.find(localizability ? "planar surfaces constrain"
                                            : "another minimum"),
              std::string::npos)
        << s.message;
    EXPECT_TRUE(std::isinf(s.covariance(0, 0))) << s.covariance;
    EXPECT_TRUE(std::isfinite(s.covariance(2, 2))) << s.covariance;
  }
}

// The near crop 2->7 from the prior (0.55 m ahead): the guess check
// converged 0.22 m ahead of the reference with a 1 cm sigma along the road.
// The search one cell edge back along the road reaches the right minimum
// (8 cm off, 75 % of the points inliers against 69 %), but the iteration
// cap stopped it first, and an unconverged solution could not replace a
// converged one; a search run the cap stops now goes on from there.
TEST(WeakGeometry, TheSearchAlongTheRoadIsNotCutShortByTheIterationCap) {
  const Tally tally = RegisterCrops(
      WithinEightMetres, RegistrationOptions(), {{2, 7}}, Start::kPrior);
  EXPECT_EQ(tally.converged_wrong, 0) << tally.report;
  EXPECT_EQ(tally.converged_right, 1) << tally.report;
}

TEST(WeakGeometry, InputThinnedToEveryTwoHundredthPointIsNotJudged) {
  const Tally tally =
      RegisterCrops([](int k, const Eigen::Vector3d&) { return k % 200 == 0; });
  EXPECT_EQ(tally.converged_wrong, 0) << tally.report;
  EXPECT_EQ(tally.converged_right, 0) << tally.report;
  EXPECT_NE(tally.report.find("too few to check the fit"), std::string::npos)
      << tally.report;
}

}  // namespace
}  // namespace mlndt
