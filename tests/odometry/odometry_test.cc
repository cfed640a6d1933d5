#include "mlndt/odometry/odometry.h"

#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <random>

#include "lab/eval/reference_pairs.h"
#include "mlndt/cloud/io.h"
#include "mlndt/common/pose.h"
#include "mlndt/odometry/recovery.h"
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
  std::vector<ProgressEvent> events;
  ProgressFunction progress(
      [&](const ProgressEvent& e) { events.push_back(e); });
  ASSERT_TRUE(RunOdometry(OdometryOptions(),
                          paths.size(),
                          KittiLoader(paths),
                          &progress,
                          &results,
                          &summary,
                          &error))
      << error;
  const std::vector<Isometry3d> reference = ReferenceChain(paths.size());
  ASSERT_EQ(results.size(), reference.size());
  EXPECT_EQ(summary.fallbacks, 0u);
  // One event a scan: its index, the count and its verdict line.
  ASSERT_EQ(events.size(), paths.size());
  for (size_t k = 0; k < events.size(); ++k) {
    EXPECT_EQ(events[k].index, k);
    EXPECT_EQ(events[k].done, k + 1);
    EXPECT_EQ(events[k].total, paths.size());
    EXPECT_EQ(events[k].status.rfind("CONVERGENCE, layer ", 0), 0u)
        << events[k].status;
  }
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

// Runs the odometry over `paths` (KITTI stamps, 10 Hz); the scan at index
// `replaced` (if any) is given by `replace` instead of its file.
void RunWithReplacedScan(const std::vector<std::string>& paths,
                         size_t replaced,
                         const std::function<void(PointCloud*)>& replace,
                         std::vector<OdometryResult>* results,
                         OdometrySummary* summary) {
  const OdometryScanLoader kitti = KittiLoader(paths);
  const OdometryScanLoader load = [&](size_t i,
                                      PointCloud* cloud,
                                      std::vector<double>* times,
                                      double* stamp_s,
                                      std::string* error) {
    if (!kitti(i, cloud, times, stamp_s, error)) return false;
    if (i == replaced) replace(cloud);
    return true;
  };
  std::string error;
  ASSERT_TRUE(RunOdometry(
      OdometryOptions(), paths.size(), load, {}, results, summary, &error))
      << error;
  ASSERT_EQ(results->size(), paths.size());
}

// Scans 0-7 of KITTI with scan `k` unregistrable: it is flagged (not
// CONVERGENCE), searched for, left out of the map, and its pose is the one
// interpolated between its registered neighbours (bridged by scan k+1);
// every other scan is registered and follows the consensus chain, and the
// map keeps every keyframe it had (no restart).
void ExpectBridged(const std::vector<OdometryResult>& results,
                   const OdometrySummary& summary,
                   size_t k,
                   bool searched = true) {
  const std::vector<Isometry3d> reference = ReferenceChain(results.size());
  const OdometryResult& bad = results[k];
  EXPECT_TRUE(bad.fallback) << bad.message;
  EXPECT_NE(bad.termination_type, TerminationType::CONVERGENCE);
  EXPECT_EQ(bad.search_starts > 0, searched);
  EXPECT_FALSE(bad.recovered);
  EXPECT_FALSE(bad.keyframe);
  EXPECT_TRUE(bad.interpolated);
  for (const auto& r : results)
    std::cerr << "DBG " << r.index << " "
              << TerminationTypeToString(r.termination_type) << " fb "
              << r.fallback << " br " << r.bridged.size() << " ss "
              << r.search_starts << " " << r.message << "\n";
  ASSERT_EQ(results[k + 1].bridged.size(), 1u);
  EXPECT_EQ(results[k + 1].bridged[0].index, k);
  const Isometry3d interpolated =
      InterpolatePose(results[k - 1].world_from_sensor,
                      results[k - 1].stamp_s,
                      results[k + 1].world_from_sensor,
                      results[k + 1].stamp_s,
                      bad.stamp_s);
  EXPECT_LT(TranslationErrorM(bad.world_from_sensor, interpolated), 1e-9);
  // The car drives straight at about 8 m/s: the interpolation is close.
  EXPECT_LT(TranslationErrorM(bad.world_from_sensor, reference[k]), 0.10);
  EXPECT_EQ(summary.fallbacks, 1u);
  EXPECT_EQ(summary.interpolated, 1u);
  EXPECT_EQ(summary.searched, searched ? 1u : 0u);
  for (size_t i = 0; i < results.size(); ++i) {
    if (i == k) continue;
    EXPECT_EQ(results[i].termination_type, TerminationType::CONVERGENCE)
        << i << ": " << results[i].message;
    EXPECT_LT(TranslationErrorM(results[i].world_from_sensor, reference[i]),
              0.10)
        << "scan " << i;
    EXPECT_LT(RotationErrorRad(results[i].world_from_sensor, reference[i]) *
                  kRadToDeg,
              0.2)
        << "scan " << i;
  }
  // The map kept its keyframes: the scan after the gap registers onto as
  // many as before it, plus itself when it is one.
  EXPECT_GE(results[k + 1].map_keyframes, results[k - 1].map_keyframes);
}

std::vector<std::string> KittiPaths() {
  std::vector<std::string> paths;
  for (size_t i = 0; i < 8; ++i) paths.push_back(KittiScan(i));
  return paths;
}

TEST(Odometry, AnEmptyScanIsAFailureInterpolatedBetweenItsNeighbours) {
  std::vector<OdometryResult> results;
  OdometrySummary summary;
  ASSERT_NO_FATAL_FAILURE(RunWithReplacedScan(
      KittiPaths(),
      4,
      [](PointCloud* cloud) { *cloud = PointCloud(); },
      &results,
      &summary));
  EXPECT_EQ(results[4].termination_type, TerminationType::FAILURE);
  EXPECT_EQ(results[4].message, "no points");
  ExpectBridged(results, summary, 4, false);  // Nothing to search with.
}

// A scan of noise: 5000 points uniform in a 40 m box around the sensor.
TEST(Odometry, AGarbageScanIsFlaggedAndInterpolatedBetweenItsNeighbours) {
  std::vector<OdometryResult> results;
  OdometrySummary summary;
  ASSERT_NO_FATAL_FAILURE(RunWithReplacedScan(
      KittiPaths(),
      3,
      [](PointCloud* cloud) {
        std::mt19937 random(7);
        std::uniform_real_distribution<double> uniform(-20.0, 20.0);
        *cloud = PointCloud();
        for (int i = 0; i < 5000; ++i) {
          cloud->Add(Eigen::Vector3d(
              uniform(random), uniform(random), 0.1 * uniform(random)));
        }
      },
      &results,
      &summary));
  ExpectBridged(results, summary, 3);
}

// A scan of another place (the koide3 Velodyne scan) after KITTI frames: the
// registration cannot place it, so it is flagged, the verdict is not
// CONVERGENCE, and it is bridged by the next KITTI frame, which is placed
// again.
TEST(Odometry, AScanOfAnotherPlaceIsBridged) {
  std::vector<std::string> paths = KittiPaths();
  paths[3] = BundledDataPath("koide3/251370668.pcd");
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
  ExpectBridged(results, summary, 3);
  EXPECT_FALSE(summary.AllUsable());
}

// Three foreign scans in a row: none restarts the map (before issue 42 the
// map restarted at the prediction of the fourth); the uncertainty grows
// with each skipped scan, the KITTI frame after them registers onto the map
// of frames 0-2 and bridges all three.
TEST(Odometry, ScansAfterAGapRegisterOntoTheMapThatKeptWhatItKnew) {
  std::vector<std::string> paths = KittiPaths();
  paths[3] = BundledDataPath("koide3/251370668.pcd");
  paths[4] = BundledDataPath("koide3/251371071.pcd");
  paths[5] = BundledDataPath("room/room_scan1.pcd");
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
  for (size_t k = 3; k < 6; ++k) {
    EXPECT_TRUE(results[k].fallback) << k << ": " << results[k].message;
    EXPECT_TRUE(results[k].interpolated) << k;
    EXPECT_LT(TranslationErrorM(results[k].world_from_sensor, reference[k]),
              0.2)
        << k;
  }
  // Scan 3 is the first predicted from model errors (0.1 m, the floor).
  EXPECT_NEAR(results[3].uncertainty.translation_m, 0.1, 1e-9);
  EXPECT_NEAR(results[4].uncertainty.translation_m, 0.2, 1e-9);
  EXPECT_NEAR(results[5].uncertainty.translation_m, 0.3, 1e-9);
  EXPECT_NEAR(results[6].uncertainty.translation_m, 0.4, 1e-9);
  ASSERT_EQ(results[6].bridged.size(), 3u);
  EXPECT_EQ(summary.interpolated, 3u);
  for (size_t k = 6; k < 8; ++k) {
    EXPECT_EQ(results[k].termination_type, TerminationType::CONVERGENCE)
        << k << ": " << results[k].message;
    EXPECT_LT(TranslationErrorM(results[k].world_from_sensor, reference[k]),
              0.1)
        << k;
  }
  EXPECT_GE(results[6].map_keyframes, results[2].map_keyframes);
}

// Point times that are not finite do not stop the run: a scan with some is
// deskewed without those points, one with none finite is a scan without
// points (FAILURE, flagged), and the next scan registers again.
TEST(Odometry, PointsWithoutAFiniteTimeAreRemovedNotFatal) {
  Odometry odometry{OdometryOptions()};
  std::vector<OdometryResult> results(6);
  std::string error;
  for (size_t k = 0; k < results.size(); ++k) {
    PointCloud cloud;
    ASSERT_TRUE(ReadPointCloud(KittiScan(k), &cloud, nullptr, &error)) << error;
    std::vector<double> times(cloud.size(), 0.0);
    if (k == 3) {
      for (size_t i = 0; i < times.size(); i += 10) times[i] = NAN;
    }
    if (k == 4) times.assign(cloud.size(), NAN);
    ASSERT_TRUE(odometry.Process(
        {0.1 * static_cast<double>(k), &cloud, &times}, &results[k], &error))
        << "scan " << k << ": " << error;
  }
  EXPECT_EQ(results[3].termination_type, TerminationType::CONVERGENCE)
      << results[3].message;
  EXPECT_NE(results[3].message.find("without a finite time removed"),
            std::string::npos)
      << results[3].message;
  EXPECT_EQ(results[4].termination_type, TerminationType::FAILURE);
  EXPECT_TRUE(results[4].fallback);
  EXPECT_EQ(results[5].termination_type, TerminationType::CONVERGENCE)
      << results[5].message;
  const std::vector<Isometry3d> chain = ReferenceChain(6);
  EXPECT_LT(TranslationErrorM(results[5].world_from_sensor, chain[5]), 0.1);
}

TEST(Odometry, RefusesStampsThatDoNotIncreaseAndAnEmptyFirstScan) {
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
  const std::vector<double> times(3, 0.0);
  EXPECT_FALSE(odometry.Process({6.0, &cloud, &times}, &result, &error));
  EXPECT_NE(error.find("3 point times for"), std::string::npos) << error;
  EXPECT_FALSE(odometry.Process({6.0, nullptr, nullptr}, &result, &error));
  EXPECT_NE(error.find("no points"), std::string::npos) << error;
  EXPECT_EQ(odometry.num_processed(), 1u);
  // The first scan must have points (it starts the map); a later one
  // without is a FAILURE, not an error.
  Odometry fresh{OdometryOptions()};
  const PointCloud empty;
  EXPECT_FALSE(fresh.Process({6.0, &empty, nullptr}, &result, &error));
  EXPECT_NE(error.find("no points"), std::string::npos) << error;
}

}  // namespace
}  // namespace mlndt
