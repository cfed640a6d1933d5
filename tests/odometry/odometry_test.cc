#include "mlndt/odometry/odometry.h"

#include <gtest/gtest.h>

#include <map>

#include "lab/eval/reference_pairs.h"
#include "mlndt/cloud/io.h"
#include "mlndt/common/pose.h"
#include "mlndt/odometry/run_odometry.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

using testing::BundledDataPath;

std::string KittiScan(size_t i) {
  return BundledDataPath("kitti/pcd/00000" + std::to_string(i) + ".pcd");
}

// Scans 0..7 of the bundled KITTI frames, stamped 0.1 s apart (10 Hz).
OdometryScanLoader KittiLoader(const std::vector<std::string>& paths) {
  return [paths](size_t i,
                 PointCloud* cloud,
                 std::vector<double>* times,
                 double* stamp_s,
                 std::string* error) {
    times->clear();
    *stamp_s = 0.1 * static_cast<double>(i);
    return ReadPointCloud(paths.at(i), cloud, nullptr, error);
  };
}

// The consensus chain of consecutive reference pairs: world_from_scan k with
// scan 0 the world.
std::vector<Isometry3d> ReferenceChain(size_t n) {
  std::map<std::string, ReferencePair> pairs;
  std::string error;
  EXPECT_TRUE(ReadReferencePairs(
      BundledDataPath("kitti/reference_pairs.json"), &pairs, &error))
      << error;
  std::vector<Isometry3d> chain = {Isometry3d::Identity()};
  for (size_t k = 1; k < n; ++k) {
    chain.push_back(chain.back() *
                    pairs.at(ReferencePairKey(k - 1, k)).reference_from_input);
  }
  return chain;
}

// Scan-to-local-map odometry over KITTI 00 frames 0-7 (about 6 m of driving)
// stays within 10 cm and 0.2 deg of the five-method consensus chain at every
// scan, with every verdict usable.
TEST(Odometry, BundledKittiFramesFollowTheConsensusChain) {
  std::vector<std::string> paths;
  for (size_t i = 0; i < 8; ++i) paths.push_back(KittiScan(i));
  std::vector<OdometryResult> results;
  OdometrySummary summary;
  std::string error;
  ASSERT_TRUE(RunOdometry(OdometryOptions(),
                          paths.size(),
                          KittiLoader(paths),
                          {},
                          &results,
                          &summary,
                          &error))
      << error;
  const std::vector<Isometry3d> reference = ReferenceChain(paths.size());
  ASSERT_EQ(results.size(), reference.size());
  EXPECT_EQ(summary.fallbacks, 0u);
  for (size_t k = 0; k < results.size(); ++k) {
    EXPECT_FALSE(results[k].fallback) << k << ": " << results[k].message;
    EXPECT_LT(TranslationErrorM(results[k].world_from_sensor, reference[k]),
              0.10)
        << "scan " << k;
    EXPECT_LT(RotationErrorRad(results[k].world_from_sensor, reference[k]) *
                  kRadToDeg,
              0.2)
        << "scan " << k;
  }
  EXPECT_GE(summary.keyframes, 2u);  // About 0.8 m a frame, 0.5 m apart.
  // Once the velocity is known the prediction is tight: a finer start.
  EXPECT_LT(results.back().uncertainty.translation_m,
            OdometryOptions().prediction.max_translation_m);
}

// A scan of another place (the koide3 Velodyne scan) after KITTI frames: the
// registration cannot place it, so the prediction stands in, flagged, and
// the verdict is not CONVERGENCE; the next KITTI frame is placed again.
TEST(Odometry, AScanOfAnotherPlaceFallsBackToThePrediction) {
  std::vector<std::string> paths = {KittiScan(0),
                                    KittiScan(1),
                                    KittiScan(2),
                                    BundledDataPath("koide3/251370668.pcd"),
                                    KittiScan(4)};
  std::vector<OdometryResult> results;
  OdometrySummary summary;
  std::string error;
  ASSERT_TRUE(RunOdometry(OdometryOptions(),
                          paths.size(),
                          KittiLoader(paths),
                          {},
                          &results,
                          &summary,
                          &error))
      << error;
  ASSERT_EQ(results.size(), 5u);
  EXPECT_TRUE(results[3].fallback) << results[3].message;
  EXPECT_NE(results[3].termination, TerminationType::CONVERGENCE);
  EXPECT_EQ(results[3].world_from_sensor.matrix(),
            results[3].predicted.matrix());
  EXPECT_FALSE(results[3].keyframe);
  EXPECT_FALSE(summary.AllUsable());
  const std::vector<Isometry3d> reference = ReferenceChain(5);
  EXPECT_FALSE(results[4].fallback) << results[4].message;
  EXPECT_LT(TranslationErrorM(results[4].world_from_sensor, reference[4]), 0.1);
}

// Three foreign scans in a row: the local map is dropped and restarts from
// the next scan, at its prediction, flagged; the scan after it registers
// onto the new map.
TEST(Odometry, TheLocalMapRestartsAfterConsecutiveFallbacks) {
  std::vector<std::string> paths = {KittiScan(0),
                                    KittiScan(1),
                                    KittiScan(2),
                                    BundledDataPath("koide3/251370668.pcd"),
                                    BundledDataPath("koide3/251371071.pcd"),
                                    BundledDataPath("room/room_scan1.pcd"),
                                    KittiScan(6),
                                    KittiScan(7)};
  OdometryOptions options;
  options.max_consecutive_fallbacks = 3;
  std::vector<OdometryResult> results;
  OdometrySummary summary;
  std::string error;
  ASSERT_TRUE(RunOdometry(options,
                          paths.size(),
                          KittiLoader(paths),
                          {},
                          &results,
                          &summary,
                          &error))
      << error;
  for (size_t k = 3; k < 6; ++k) {
    EXPECT_TRUE(results[k].fallback) << k << ": " << results[k].message;
    EXPECT_FALSE(results[k].map_restarted) << k;
  }
  EXPECT_TRUE(results[6].map_restarted);
  EXPECT_TRUE(results[6].fallback);
  EXPECT_TRUE(results[6].keyframe);
  EXPECT_EQ(results[6].map_keyframes, 1u);
  EXPECT_NE(results[6].message.find("no pose for 3 scans"), std::string::npos)
      << results[6].message;
  EXPECT_FALSE(results[7].fallback) << results[7].message;
  EXPECT_EQ(summary.map_restarts, 1u);
}

TEST(Odometry, RefusesStampsThatDoNotIncreaseAndEmptyScans) {
  Odometry odometry{OdometryOptions()};
  PointCloud cloud;
  std::string error;
  ASSERT_TRUE(ReadPointCloud(KittiScan(0), &cloud, nullptr, &error)) << error;
  OdometryResult result;
  ASSERT_TRUE(odometry.Process({5.0, &cloud, nullptr}, &result, &error))
      << error;
  EXPECT_FALSE(odometry.Process({5.0, &cloud, nullptr}, &result, &error));
  EXPECT_NE(error.find("is not after the previous scan's 5"), std::string::npos)
      << error;
  const PointCloud empty;
  EXPECT_FALSE(odometry.Process({6.0, &empty, nullptr}, &result, &error));
  EXPECT_NE(error.find("no points"), std::string::npos) << error;
  const std::vector<double> times(3, 0.0);
  EXPECT_FALSE(odometry.Process({6.0, &cloud, &times}, &result, &error));
  EXPECT_NE(error.find("3 point times for"), std::string::npos) << error;
  EXPECT_EQ(odometry.num_processed(), 1u);
}

}  // namespace
}  // namespace mlndt
