#include "mlndt/pipeline/localizer.h"

#include <glog/logging.h>
#include <gtest/gtest.h>

#include <string>
#include <variant>
#include <vector>

#include "mlndt/common/pose.h"
#include "mlndt/common/result_table.h"
#include "tests/testing/synthetic_scene.h"

namespace mlndt {
namespace {

// A drive along the synthetic street: the map is one sampling of the
// scene, each scan another sampling (its own seed) seen from the vehicle,
// points within 30 m, in the vehicle frame.
struct Drive {
  LayeredGrid map;
  std::vector<Isometry3d> map_from_scan;
  std::vector<PointCloud> scans;
};

const Drive& StreetDrive() {
  static const Drive* drive = [] {
    auto* d = new Drive;
    const PointCloud scene = testing::StreetScene(150000, 0.01, 1);
    std::string error;
    CHECK(LayeredGrid::Build(LayeredGridOptions(), scene, &d->map, &error))
        << error;
    for (int k = 0; k < 6; ++k) {
      // 1.5 m and 2 degrees of yaw a scan, a little pitch and height.
      const Isometry3d map_from_scan =
          PoseVectorToIsometry(PoseVectorFromDegrees(
              -10.0 + 1.5 * k, 0.3 * k, 1.7, 0.2, -0.3, 2.0 * k));
      const PointCloud world = testing::StreetScene(40000, 0.01, 10 + k);
      PointCloud scan;
      const Eigen::Vector3d sensor = map_from_scan.translation();
      for (const Eigen::Vector3d& p : world.points()) {
        if ((p - sensor).norm() < 30.0) scan.Add(map_from_scan.inverse() * p);
      }
      d->map_from_scan.push_back(map_from_scan);
      d->scans.push_back(scan);
    }
    return d;
  }();
  return *drive;
}

// Runs LocalizeScans over the drive, recording the loads.
bool RunDrive(const LocalizerOptions& options,
              const Isometry3d& first_guess,
              std::vector<LocalizationResult>* results,
              std::vector<size_t>* loads,
              std::string* error) {
  const Drive& drive = StreetDrive();
  const ScanLoader load = [&](size_t k, PointCloud* scan, std::string*) {
    loads->push_back(k);
    *scan = drive.scans[k];
    return true;
  };
  return LocalizeScans(options,
                       drive.map,
                       first_guess,
                       drive.scans.size(),
                       load,
                       nullptr,
                       results,
                       error);
}

// From a first guess 2 m and 10 degrees off, every scan lands on its true
// pose; each scan is loaded once, in order; the predictions follow the
// constant-velocity rule exactly.
TEST(LocalizeScans, ConstantVelocityFindsEveryPose) {
  const Drive& drive = StreetDrive();
  const Isometry3d first_guess =
      drive.map_from_scan[0] *
      PoseVectorToIsometry(PoseVectorFromDegrees(2.0, -1.0, 0, 0, 0, 10.0));
  std::vector<LocalizationResult> results;
  std::vector<size_t> loads;
  std::string error;
  ASSERT_TRUE(
      RunDrive(LocalizerOptions(), first_guess, &results, &loads, &error))
      << error;
  ASSERT_EQ(results.size(), drive.scans.size());
  EXPECT_EQ(loads, (std::vector<size_t>{0, 1, 2, 3, 4, 5}));
  for (size_t k = 0; k < results.size(); ++k) {
    SCOPED_TRACE("scan " + std::to_string(k));
    const LocalizationResult& r = results[k];
    EXPECT_EQ(r.index, k);
    EXPECT_EQ(r.registration.termination_type, TerminationType::CONVERGENCE)
        << r.registration.message;
    EXPECT_LT(TranslationErrorM(drive.map_from_scan[k], r.map_from_scan), 0.05);
    EXPECT_LT(
        RotationErrorRad(drive.map_from_scan[k], r.map_from_scan) * kRadToDeg,
        0.3);
    EXPECT_GT(r.registration.quality.inlier_fraction, 0.5);
    EXPECT_GT(r.registration.sampled_points, 0u);
    EXPECT_GT(r.registration.total_time_s, 0.0);
    EXPECT_GE(r.load_time_s, 0.0);
    Isometry3d expected_prediction = first_guess;
    if (k == 1) expected_prediction = results[0].map_from_scan;
    if (k >= 2) {
      const Isometry3d& p1 = results[k - 1].map_from_scan;
      const Isometry3d& p2 = results[k - 2].map_from_scan;
      expected_prediction = p1 * (p2.inverse() * p1);
    }
    EXPECT_TRUE(r.predicted_map_from_scan.isApprox(expected_prediction, 1e-12));
  }
}

TEST(Localizer, ConstantPosePredictsThePreviousPose) {
  const Drive& drive = StreetDrive();
  LocalizerOptions options;
  options.motion_model = MotionModel::CONSTANT_POSE;
  // No prior: the registration starts from the prediction alone (with one,
  // the best of the explored starts' summaries is kept).
  options.adapt_prediction_uncertainty = false;
  Localizer localizer(options, drive.map, drive.map_from_scan[0]);
  EXPECT_TRUE(localizer.PredictNext().isApprox(drive.map_from_scan[0]));
  LocalizationResult first, second;
  localizer.Localize(drive.scans[0], &first);
  EXPECT_TRUE(localizer.PredictNext().isApprox(first.map_from_scan, 1e-12));
  localizer.Localize(drive.scans[1], &second);
  EXPECT_TRUE(
      second.predicted_map_from_scan.isApprox(first.map_from_scan, 1e-12));
  // The result holds the registration's whole summary: its guess was the
  // prediction, its solution is the estimate.
  const RegistrationSummary& summary = second.registration;
  EXPECT_TRUE(summary.reference_from_input.isApprox(second.map_from_scan));
  EXPECT_TRUE(IsometryToPoseVector(second.predicted_map_from_scan)
                  .isApprox(summary.initial_reference_from_input_xi, 1e-9));
  EXPECT_EQ(summary.num_iterations, static_cast<int>(summary.trace.size()));
  EXPECT_GT(summary.num_iterations, 0);
  EXPECT_EQ(localizer.num_localized(), 2u);
}

// A scan with no points fails: its pose is the prediction, and the next
// prediction is the last usable pose (no prediction from a pose that is only
// a prediction).
TEST(Localizer, FailurePredictsFromTheLastUsablePose) {
  const Drive& drive = StreetDrive();
  Localizer localizer(LocalizerOptions(), drive.map, drive.map_from_scan[0]);
  LocalizationResult r0, r1, r2, r3;
  localizer.Localize(drive.scans[0], &r0);
  localizer.Localize(drive.scans[1], &r1);
  const Isometry3d motion = r0.map_from_scan.inverse() * r1.map_from_scan;
  localizer.Localize(PointCloud(), &r2);
  EXPECT_EQ(r2.registration.termination_type, TerminationType::FAILURE);
  EXPECT_FALSE(r2.IsSolutionUsable());
  EXPECT_FALSE(r2.registration.message.empty());
  EXPECT_TRUE(r2.map_from_scan.isApprox(r1.map_from_scan * motion, 1e-12));
  EXPECT_TRUE(r2.predicted_map_from_scan.isApprox(r2.map_from_scan, 1e-12));
  EXPECT_TRUE(localizer.PredictNext().isApprox(r1.map_from_scan, 1e-12));
  localizer.Localize(drive.scans[3], &r3);
  EXPECT_EQ(r3.registration.termination_type, TerminationType::CONVERGENCE);
  EXPECT_LT(TranslationErrorM(drive.map_from_scan[3], r3.map_from_scan), 0.05);
}

// Issue 27 item 1: a scan's result is usable exactly when a registration's
// is (LOW_QUALITY and DEGENERATE were counted as usable by the localiser).
TEST(LocalizationResult, UsableExactlyWhenTheRegistrationIs) {
  for (const TerminationType type : {TerminationType::CONVERGENCE,
                                     TerminationType::NO_CONVERGENCE,
                                     TerminationType::LOW_QUALITY,
                                     TerminationType::DEGENERATE,
                                     TerminationType::FAILURE}) {
    LocalizationResult result;
    result.registration.termination_type = type;
    EXPECT_EQ(result.IsSolutionUsable(), result.registration.IsSolutionUsable())
        << TerminationTypeToString(type);
    EXPECT_EQ(result.IsSolutionUsable(),
              type == TerminationType::CONVERGENCE ||
                  type == TerminationType::NO_CONVERGENCE)
        << TerminationTypeToString(type);
  }
}

TEST(LocalizeScans, StopsAtAScanThatCannotBeLoaded) {
  const Drive& drive = StreetDrive();
  std::vector<LocalizationResult> results;
  std::vector<size_t> calls;
  const ScanLoader load = [&](size_t k, PointCloud* scan, std::string* error) {
    calls.push_back(k);
    if (k == 2) {
      *error = "scan 2: unreadable";
      return false;
    }
    *scan = drive.scans[k];
    return true;
  };
  std::vector<ProgressEvent> reported;
  ProgressFunction progress(
      [&](const ProgressEvent& e) { reported.push_back(e); });
  std::string error;
  EXPECT_FALSE(LocalizeScans(LocalizerOptions(),
                             drive.map,
                             drive.map_from_scan[0],
                             drive.scans.size(),
                             load,
                             &progress,
                             &results,
                             &error));
  EXPECT_EQ(error, "scan 2: unreadable");
  EXPECT_EQ(calls, (std::vector<size_t>{0, 1, 2}));
  // One event a localised scan: its index, the count and its verdict line.
  ASSERT_EQ(reported.size(), 2u);
  for (size_t k = 0; k < reported.size(); ++k) {
    EXPECT_EQ(reported[k].index, k);
    EXPECT_EQ(reported[k].done, k + 1);
    EXPECT_EQ(reported[k].total, drive.scans.size());
    EXPECT_EQ(reported[k].status.rfind("CONVERGENCE, inliers ", 0), 0u)
        << reported[k].status;
  }
  EXPECT_EQ(results.size(), 2u);
}

TEST(LocalizeScans, RefusesInvalidOptionsAndAnEmptyMap) {
  std::vector<LocalizationResult> results;
  std::vector<size_t> loads;
  std::string error;
  LocalizerOptions options;
  options.registration.num_threads = 0;
  EXPECT_FALSE(
      RunDrive(options, Isometry3d::Identity(), &results, &loads, &error));
  EXPECT_NE(error.find("num_threads"), std::string::npos) << error;
  options = LocalizerOptions();
  options.motion_model = static_cast<MotionModel>(7);
  EXPECT_FALSE(
      RunDrive(options, Isometry3d::Identity(), &results, &loads, &error));
  EXPECT_NE(error.find("motion_model"), std::string::npos) << error;
  EXPECT_TRUE(loads.empty());
  EXPECT_FALSE(LocalizeScans(
      LocalizerOptions(),
      LayeredGrid(),
      Isometry3d::Identity(),
      1,
      [](size_t, PointCloud*, std::string*) { return true; },
      nullptr,
      &results,
      &error));
  EXPECT_NE(error.find("map is empty"), std::string::npos) << error;
}

TEST(MotionModel, Strings) {
  MotionModel model;
  EXPECT_TRUE(StringToMotionModel("constant_pose", &model));
  EXPECT_EQ(model, MotionModel::CONSTANT_POSE);
  EXPECT_TRUE(StringToMotionModel("Constant_Velocity", &model));
  EXPECT_EQ(model, MotionModel::CONSTANT_VELOCITY);
  EXPECT_STREQ(MotionModelToString(model), "CONSTANT_VELOCITY");
  EXPECT_FALSE(StringToMotionModel("linear", &model));
}

// The table (result_table.h) holds the result's own fields and nests the
// registration's table on the result's own summary.
TEST(LocalizationResultTable, NestsTheRegistrationsSummary) {
  const Drive& drive = StreetDrive();
  const Isometry3d guess =
      drive.map_from_scan[0] *
      PoseVectorToIsometry(PoseVectorFromDegrees(1.0, 0, 0, 0, 0, 5.0));
  Localizer localizer(LocalizerOptions(), drive.map, guess);
  LocalizationResult result;
  localizer.Localize(drive.scans[0], &result);
  const ResultTable& table = LocalizationResultTable();
  std::vector<std::string> names;
  for (const ResultField& field : table.fields()) names.push_back(field.name);
  EXPECT_EQ(names,
            (std::vector<std::string>{"index",
                                      "usable",
                                      "predicted_map_from_scan",
                                      "map_from_scan",
                                      "map_from_scan_xi",
                                      "correction_m",
                                      "correction_rad",
                                      "load_time_s",
                                      "registration"}));
  const ResultField* registration = table.Find("registration");
  ASSERT_NE(registration, nullptr);
  EXPECT_EQ(registration->nested, &RegistrationSummaryTable());
  const auto nested = std::get<NestedResult>(registration->Get(result));
  EXPECT_EQ(nested.object, static_cast<const void*>(&result.registration));
  const auto pose =
      std::get<Eigen::MatrixXd>(table.Find("map_from_scan")->Get(result));
  EXPECT_TRUE(pose.isApprox(result.map_from_scan.matrix()));
  EXPECT_NEAR(std::get<double>(table.Find("correction_m")->Get(result)),
              TranslationErrorM(guess, result.map_from_scan),
              1e-12);
  EXPECT_NEAR(
      std::get<double>(table.Find("correction_m")->Get(result)), 1.0, 0.05);
  EXPECT_NEAR(std::get<double>(table.Find("correction_rad")->Get(result)),
              5.0 * kDegToRad,
              0.01);
}

}  // namespace
}  // namespace mlndt
