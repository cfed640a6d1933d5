// The localiser's prior (localization_prior.h, Localizer::PredictionPrior):
// a result outside the stated prior is not usable, the prediction after an
// unusable scan is the last usable pose with a prior that grows with the
// gap, and a guess whose prior is not stated keeps the registration's
// verdict. The street scene of localizer_test.cc, rebuilt here.

#include "mlndt/pipeline/localization_prior.h"

#include <glog/logging.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "mlndt/common/pose.h"
#include "mlndt/pipeline/localizer.h"
#include "tests/testing/synthetic_scene.h"

namespace mlndt {
namespace {

struct Street {
  LayeredGrid map;
  Isometry3d map_from_scan;
  PointCloud scan;
};

const Street& TheStreet() {
  static const Street* street = [] {
    auto* s = new Street;
    const PointCloud scene = testing::StreetScene(150000, 0.01, 1);
    std::string error;
    CHECK(LayeredGrid::Build(LayeredGridOptions(), scene, &s->map, &error))
        << error;
    s->map_from_scan = PoseVectorToIsometry(
        PoseVectorFromDegrees(-4.0, 0.6, 1.7, 0.2, -0.3, 8.0));
    const PointCloud world = testing::StreetScene(40000, 0.01, 10);
    const Eigen::Vector3d sensor = s->map_from_scan.translation();
    for (const Eigen::Vector3d& p : world.points()) {
      if ((p - sensor).norm() < 30.0)
        s->scan.Add(s->map_from_scan.inverse() * p);
    }
    return s;
  }();
  return *street;
}

Isometry3d Offset(double x_m, double y_m, double yaw_deg) {
  return PoseVectorToIsometry(
      PoseVectorFromDegrees(x_m, y_m, 0.0, 0.0, 0.0, yaw_deg));
}

TEST(WithinPrior, BothBoundsAndNotGiven) {
  const Isometry3d guess = Offset(1.0, 2.0, 30.0);
  InitialGuessUncertainty prior;
  EXPECT_TRUE(WithinPrior(prior, guess, guess * Offset(100.0, 0.0, 90.0)));
  prior.given = true;
  prior.translation_m = 2.0;
  prior.rotation_deg = 10.0;
  EXPECT_TRUE(WithinPrior(prior, guess, guess * Offset(1.9, 0.0, 9.0)));
  EXPECT_FALSE(WithinPrior(prior, guess, guess * Offset(2.1, 0.0, 0.0)));
  EXPECT_FALSE(WithinPrior(prior, guess, guess * Offset(0.0, 0.0, 11.0)));
}

// Started 3 m off with the guess stated good to 0.5 m: the registration
// finds the true pose, 3 m from the guess, which is not a localisation of
// that guess (LOW_QUALITY, "outside the prior"); stated good to 5 m the
// same start converges there.
TEST(RegisterWithinPrior, AResultOutsideThePriorIsNotUsable) {
  const Street& street = TheStreet();
  const Isometry3d guess = street.map_from_scan * Offset(3.0, 0.0, 0.0);
  InitialGuessUncertainty prior;
  prior.given = true;
  prior.translation_m = 0.5;
  prior.rotation_deg = 5.0;
  RegistrationSummary narrow;
  PriorCheckSummary check;
  RegisterWithinPrior(PriorCheckOptions(),
                      RegistrationOptions(),
                      street.map,
                      street.scan,
                      guess,
                      prior,
                      &narrow,
                      &check);
  EXPECT_FALSE(narrow.IsSolutionUsable()) << narrow.message;
  EXPECT_NE(narrow.message.find("outside the prior"), std::string::npos)
      << narrow.message;

  prior.translation_m = 5.0;
  RegistrationSummary wide;
  RegisterWithinPrior(PriorCheckOptions(),
                      RegistrationOptions(),
                      street.map,
                      street.scan,
                      guess,
                      prior,
                      &wide,
                      &check);
  EXPECT_EQ(wide.termination_type, TerminationType::CONVERGENCE)
      << wide.message;
  EXPECT_LT(TranslationErrorM(street.map_from_scan, wide.reference_from_input),
            0.05);
  EXPECT_GT(check.explored_starts, 0);
  EXPECT_NEAR(check.from_guess_m, 3.0, 0.05);
}

// Unusable scans (no points): the prediction stays the last usable pose
// and its prior grows by the per-scan growth, up to the maxima; a usable
// scan resets it.
TEST(Localizer, PriorGrowsWithTheGapFromTheLastUsablePose) {
  const Street& street = TheStreet();
  LocalizerOptions options;
  options.guess_translation_m = 1.0;
  options.guess_rotation_deg = 10.0;
  options.prediction_translation_m = 0.5;
  options.prediction_rotation_deg = 5.0;
  options.lost_translation_m_per_scan = 0.5;
  options.lost_rotation_deg_per_scan = 10.0;
  options.max_lost_translation_m = 1.6;
  options.max_lost_rotation_deg = 90.0;
  const Isometry3d first = street.map_from_scan * Offset(0.3, 0.0, 2.0);
  Localizer localizer(options, street.map, first);
  EXPECT_DOUBLE_EQ(localizer.PredictionPrior().translation_m, 1.0);
  LocalizationResult r;
  localizer.Localize(street.scan, &r);
  ASSERT_EQ(r.registration.termination_type, TerminationType::CONVERGENCE)
      << r.registration.message;
  const Isometry3d usable = r.map_from_scan;
  EXPECT_DOUBLE_EQ(localizer.PredictionPrior().translation_m, 0.5);
  EXPECT_DOUBLE_EQ(localizer.PredictionPrior().rotation_deg, 5.0);
  localizer.Localize(PointCloud(), &r);
  EXPECT_FALSE(r.IsSolutionUsable());
  EXPECT_TRUE(localizer.PredictNext().isApprox(usable, 1e-12));
  EXPECT_DOUBLE_EQ(localizer.PredictionPrior().translation_m, 1.0);
  EXPECT_DOUBLE_EQ(localizer.PredictionPrior().rotation_deg, 15.0);
  localizer.Localize(PointCloud(), &r);
  localizer.Localize(PointCloud(), &r);
  EXPECT_TRUE(localizer.PredictNext().isApprox(usable, 1e-12));
  EXPECT_DOUBLE_EQ(localizer.PredictionPrior().translation_m, 1.6);
  EXPECT_DOUBLE_EQ(localizer.PredictionPrior().rotation_deg, 35.0);
  localizer.Localize(street.scan, &r);
  EXPECT_EQ(r.registration.termination_type, TerminationType::CONVERGENCE)
      << r.registration.message;
  EXPECT_DOUBLE_EQ(localizer.PredictionPrior().translation_m, 0.5);
}

// No prior stated: the registration's verdict stands (the guess 3 m off
// converges, no start is explored).
TEST(Localizer, NoPriorStatedKeepsTheRegistrationsVerdict) {
  const Street& street = TheStreet();
  const Isometry3d guess = street.map_from_scan * Offset(3.0, 0.0, 0.0);
  Localizer localizer(LocalizerOptions(), street.map, guess);
  EXPECT_FALSE(localizer.PredictionPrior().given);
  LocalizationResult r;
  localizer.LocalizeFrom(street.scan, guess, &r);
  EXPECT_EQ(r.registration.termination_type, TerminationType::CONVERGENCE);
  EXPECT_LT(TranslationErrorM(street.map_from_scan, r.map_from_scan), 0.05);
}

}  // namespace
}  // namespace mlndt
