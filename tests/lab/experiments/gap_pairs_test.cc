#include "lab/experiments/gap_pairs.h"

#include <gtest/gtest.h>

#include "lab/experiments/covariance_campaign.h"
#include "mlndt/common/pose.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

std::vector<PointCloud> FirstKittiScans(size_t n,
                                        std::vector<Isometry3d>* poses) {
  std::vector<PointCloud> scans;
  std::string error;
  EXPECT_TRUE(ReadBundledKittiFrames(
      testing::BundledDataPath("kitti"), &scans, poses, &error))
      << error;
  scans.resize(n);
  return scans;
}

// KITTI frames 0-2 from the identity: pairs 0->1 and 1->2 (gap 1), then
// 0->2 (gap 2), in that order, each called back once and right within
// 0.5 m / 1 deg of the ground truth (KITTI's poses are ~0.17 m a frame off
// the scans' own motion: mlndt_pairs reports 0.17 m for 0->1, 0.33 m for
// 0->2).
TEST(RunGapPairs, RegistersEveryGapInOrderFromTheIdentity) {
  std::vector<Isometry3d> poses;
  const std::vector<PointCloud> scans = FirstKittiScans(3, &poses);
  GapPairsOptions pairs;
  pairs.gaps = {1, 2};
  pairs.max_translation_error_m = 0.5;
  std::vector<GapPairRun> runs;
  RunGapPairs(
      pairs, RegistrationOptions(), scans, poses, [&](const GapPairRun& r) {
        runs.push_back(r);
      });
  ASSERT_EQ(runs.size(), 3u);
  const size_t expected[3][3] = {{0, 1, 1}, {1, 2, 1}, {0, 2, 2}};
  for (size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(runs[k].reference, expected[k][0]);
    EXPECT_EQ(runs[k].input, expected[k][1]);
    EXPECT_EQ(runs[k].gap, expected[k][2]);
    EXPECT_EQ(runs[k].start, "identity");
    EXPECT_TRUE(runs[k].success)
        << k << ": " << runs[k].translation_error_m << " m, "
        << runs[k].rotation_error_deg << " deg";
    EXPECT_GT(runs[k].iterations, 0);
  }
}

// A start 30 m off with a threshold of 1 cm: the result is scored against
// the truth, and the label names the offset in m and deg.
TEST(RunGapPairs, ScoresPerturbedStartsAgainstTheTruth) {
  std::vector<Isometry3d> poses;
  const std::vector<PointCloud> scans = FirstKittiScans(2, &poses);
  GapPairsOptions pairs;
  pairs.perturbations = {PoseVectorFromDegrees(30, 0, 0, 0, 0, 90)};
  pairs.max_translation_error_m = 0.01;
  std::vector<GapPairRun> runs;
  RunGapPairs(
      pairs, RegistrationOptions(), scans, poses, [&](const GapPairRun& r) {
        runs.push_back(r);
      });
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_EQ(runs[0].start, "gt+(30,0,0,0,0,90)");
  EXPECT_FALSE(runs[0].success);
  EXPECT_GT(runs[0].translation_error_m, 0.01);
}

}  // namespace
}  // namespace mlndt
