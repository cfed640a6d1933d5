// The initial guess: it must be rigid; with an uncertainty it picks the
// start layer (the better the guess, the finer the start), and the result
// is never worse than a last-layer run from the guess. On the bundled
// koide3 pair against its five-peer reference.

#include <gtest/gtest.h>

#include "lab/eval/reference_pairs.h"
#include "mlndt/cloud/io.h"
#include "mlndt/common/pose.h"
#include "mlndt/registration/registration.h"
#include "mlndt/schedule/layer_scheduler.h"
#include "tests/testing/shared_pair.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

struct Koide3 {
  PointCloud reference, input;
  Isometry3d truth = Isometry3d::Identity();
};

const Koide3& Pair() {
  static const Koide3* pair = [] {
    auto* p = new Koide3;
    std::string error;
    CHECK(ReadPointCloud(testing::BundledDataPath("koide3/251370668.pcd"),
                         &p->reference,
                         nullptr,
                         &error))
        << error;
    CHECK(ReadPointCloud(testing::BundledDataPath("koide3/251371071.pcd"),
                         &p->input,
                         nullptr,
                         &error))
        << error;
    std::map<std::string, ReferencePair> references;
    CHECK(ReadReferencePairs(
        testing::BundledDataPath("koide3/reference_pairs.json"),
        &references,
        &error))
        << error;
    p->truth = references.at("251370668_251371071").reference_from_input;
    return p;
  }();
  return *pair;
}

RegistrationSummary RegisterFrom(const Isometry3d& guess,
                                 const RegistrationOptions& options) {
  RegistrationSummary summary;
  Register(options, Pair().reference, Pair().input, guess, &summary);
  return summary;
}

TEST(InitialGuess, ANonRigidGuessIsRefused) {
  Isometry3d reflection = Isometry3d::Identity();
  reflection.linear() = Eigen::Vector3d(1, 1, -1).asDiagonal();
  Isometry3d scaled = Isometry3d::Identity();
  scaled.linear() *= 2.0;
  Isometry3d sheared = Isometry3d::Identity();
  sheared.linear()(0, 1) = 0.3;
  for (const Isometry3d& guess : {reflection, scaled, sheared}) {
    const RegistrationSummary s = RegisterFrom(guess, RegistrationOptions());
    EXPECT_EQ(s.termination_type, TerminationType::FAILURE);
    EXPECT_NE(s.message.find("not a rigid transform"), std::string::npos)
        << s.message;
  }
}

TEST(InitialGuess, AKnownUncertaintyStartsFinerAndLandsOnTheReference) {
  const Isometry3d guess =
      PoseVectorToIsometry(PoseVectorFromDegrees(0.3, -0.2, 0.05, 0, 0, 2)) *
      Pair().truth;
  const RegistrationSummary without =
      RegisterFrom(guess, RegistrationOptions());
  RegistrationOptions options;
  options.initial_uncertainty.given = true;
  options.initial_uncertainty.translation_m = 0.5;
  options.initial_uncertainty.rotation_deg = 5.0;
  const RegistrationSummary with = RegisterFrom(guess, options);
  ASSERT_TRUE(with.IsSolutionUsable()) << with.message;
  EXPECT_EQ(without.start_layer, 1);
  // Cells at least 2 x (0.5 m + 5 deg at the points' RMS range) wide.
  EXPECT_GT(with.start_layer, 1);
  EXPECT_LT(with.start_layer, with.num_layers);
  EXPECT_LT(with.num_iterations, without.num_iterations);
  EXPECT_LT(TranslationErrorM(Pair().truth, with.reference_from_input), 0.05);
  EXPECT_LT(
      RotationErrorRad(Pair().truth, with.reference_from_input) * kRadToDeg,
      0.5);
}

TEST(InitialGuess, AGoodGuessIsNotMadeWorse) {
  // From the reference itself with a tight uncertainty: the last layer only,
  // and the result stays within the references' own spread (3.3 cm).
  RegistrationOptions options;
  options.initial_uncertainty.given = true;
  options.initial_uncertainty.translation_m = 0.02;
  options.initial_uncertainty.rotation_deg = 0.2;
  const RegistrationSummary s = RegisterFrom(Pair().truth, options);
  ASSERT_EQ(s.termination_type, TerminationType::CONVERGENCE) << s.message;
  EXPECT_EQ(s.start_layer, s.num_layers);
  // The schedule, and the scan-pattern check: the koide3 input lies 0.5 m
  // from the reference, within half a last-layer cell.
  EXPECT_EQ(s.attempts, 2);
  EXPECT_LT(TranslationErrorM(Pair().truth, s.reference_from_input), 0.033);
}

// The samples the schedule's stages evaluated in the run `s` reports.
int64_t SchedulePointIterations(const RegistrationOptions& options,
                                const RegistrationSummary& s) {
  const int64_t points = static_cast<int64_t>(s.sampled_points);
  int64_t sum = 0;
  for (int layer = 1; layer <= s.num_layers; ++layer) {
    const int stride =
        StageControlFor(options.schedule, layer, s.num_layers).point_stride;
    sum += s.iterations_per_layer[static_cast<size_t>(layer - 1)] *
           ((points + stride - 1) / stride);
  }
  return sum;
}

TEST(InitialGuess, TheGuessCheckLooksOverASubsetWhenItFindsTheSameBasin) {
  // From the identity the schedule moves the koide3 input far beyond a
  // last-layer cell: the last layer alone runs from the guess, first over
  // every 8th sample. It finds the schedule's basin, so the check ends
  // there: its cost is at most a capped stage over an eighth of the points
  // (over all of them it took 22 iterations on KITTI, more than the solve).
  // The scan-pattern check, which runs on this pair too, is off here.
  RegistrationOptions options;
  options.retry.scan_pattern_reach_cells = 0.0;
  const RegistrationSummary s = RegisterFrom(Isometry3d::Identity(), options);
  ASSERT_EQ(s.termination_type, TerminationType::CONVERGENCE) << s.message;
  EXPECT_EQ(s.attempts, 2);
  const int64_t schedule = SchedulePointIterations(options, s);
  const int stride = options.schedule.max_coarse_point_stride;
  const int64_t eighth =
      (static_cast<int64_t>(s.sampled_points) + stride - 1) / stride;
  EXPECT_GT(s.point_iterations, schedule);
  EXPECT_LE(s.point_iterations - schedule,
            options.schedule.max_final_iterations * eighth);
  EXPECT_LT(TranslationErrorM(Pair().truth, s.reference_from_input), 0.033);
}

// Sparse hand-held Livox Avia scans (~5100 points, 70 deg field of view):
// the coarse layers pulled these pairs, started at their references without
// a stated uncertainty, 1.14 m (185->188) and 0.41 m (207->210) away into
// another basin. The last-layer run from the guess fits better and wins.
TEST(InitialGuess, AGoodGuessWithoutUncertaintyIsNotMadeWorseOnSparseScans) {
  MLNDT_REQUIRE_SHARED_DATA(dir);
  for (const char* key : {"185_188", "207_210"}) {
    const testing::SharedPair shared =
        testing::ReadSharedPair(dir + "/fastlio_avia_hku_2_pairs", key);
    const ReferencePair& pair = shared.pair;
    const PointCloud& reference = shared.reference;
    const PointCloud& input = shared.input;
    Isometry3d guess = pair.reference_from_input;
    guess.linear() = Eigen::Quaterniond(guess.linear()).normalized().matrix();
    RegistrationSummary s;
    Register(RegistrationOptions(), reference, input, guess, &s);
    ASSERT_TRUE(s.IsSolutionUsable()) << key << ": " << s.message;
    EXPECT_GE(s.attempts, 2) << key;
    // The prior entries are good to about 2-5 cm (the folder's README).
    EXPECT_LT(TranslationErrorM(guess, s.reference_from_input), 0.06) << key;
    EXPECT_LT(RotationErrorRad(guess, s.reference_from_input) / kDegToRad, 0.3)
        << key;
  }
}

// 211->212 has a five-peer consensus reference (GICP variants within 3 cm of
// it), and its LIO prior is 3.4 cm / 0.02 deg off. From the prior with a
// stated 0.1 m / 1 deg, the search along the flattest weak direction moved
// the result to a minimum with more inliers but a higher score than at the
// prior: 9.4 cm / 0.51 deg off. A minimum of the search must now also score
// no worse.
TEST(InitialGuess, TheSearchDoesNotTradeTheFitForInliersAtTheGatesEdge) {
  MLNDT_REQUIRE_SHARED_DATA(dir);
  const testing::SharedPair shared =
      testing::ReadSharedPair(dir + "/fastlio_avia_hku_2_pairs", "211_212");
  const ReferencePair& pair = shared.pair;
  RegistrationOptions options;
  options.initial_uncertainty.given = true;
  options.initial_uncertainty.translation_m = 0.1;
  options.initial_uncertainty.rotation_deg = 1.0;
  RegistrationSummary s;
  Register(options,
           shared.reference,
           shared.input,
           pair.prior_from_input.value(),
           &s);
  ASSERT_EQ(s.termination_type, TerminationType::CONVERGENCE) << s.message;
  EXPECT_LT(s.final_score, s.initial_score);
  EXPECT_LT(
      TranslationErrorM(pair.reference_from_input, s.reference_from_input),
      0.05);
  EXPECT_LT(
      RotationErrorRad(pair.reference_from_input, s.reference_from_input) /
          kDegToRad,
      0.25);
}

}  // namespace
}  // namespace mlndt
