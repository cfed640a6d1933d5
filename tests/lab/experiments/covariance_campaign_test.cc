#include "lab/experiments/covariance_campaign.h"

#include <gtest/gtest.h>

#include "mlndt/common/pose.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

// Bundled KITTI frames 1 -> 0 from four starts 0.2 m / 2 deg around the
// ground truth: every run is called back, the runs agree with each other
// (none is an outlier at 10 cm / 1 deg) and the pooled consistency counts
// them all.
TEST(RunCovariancePair, KittiPairFromPerturbedStarts) {
  std::vector<PointCloud> scans;
  std::vector<Isometry3d> poses;
  std::string error;
  ASSERT_TRUE(ReadBundledKittiFrames(
      testing::BundledDataPath("kitti"), &scans, &poses, &error))
      << error;
  ASSERT_EQ(scans.size(), 8u);
  ASSERT_GE(poses.size(), 2u);
  CovarianceCampaignOptions campaign;
  campaign.starts = 4;
  campaign.max_translation_m = 0.2;
  campaign.max_rotation_deg = 2.0;
  std::mt19937_64 rng(7);
  int called = 0;
  const auto on_run = [&](int k, const RegistrationSummary&, bool) {
    EXPECT_EQ(k, called);
    ++called;
  };
  PairRuns pair;
  ASSERT_TRUE(RunCovariancePair(campaign,
                                RegistrationOptions(),
                                scans[0],
                                scans[1],
                                poses[0].inverse() * poses[1],
                                &rng,
                                on_run,
                                &pair,
                                &error))
      << error;
  EXPECT_EQ(called, 4);
  EXPECT_EQ(pair.failures, 0);
  EXPECT_EQ(pair.outliers, 0);
  ASSERT_EQ(pair.runs.size(), 4u);
  for (const StartResult& run : pair.runs) {
    // Within a few decimetres of the ground truth (KITTI's poses are not
    // exact for the scans: docs in lab/programs/mlndt_covariance.cc).
    EXPECT_LT((run.xi.head<3>() - pair.reference_xi.head<3>()).norm(), 0.5);
    EXPECT_GT(run.covariance.trace(), 0.0);
  }
  Consistency sum;
  Accumulate(pair, &sum);
  const Consistency result = Finish(sum);
  EXPECT_EQ(result.runs, 4);
  EXPECT_GT(result.spread_std.head<3>().norm(), 0.0);
}

TEST(ReadBundledKittiFrames, NamesAMissingFolder) {
  std::vector<PointCloud> scans;
  std::vector<Isometry3d> poses;
  std::string error;
  EXPECT_FALSE(ReadBundledKittiFrames(
      testing::BundledDataPath("no_such_folder"), &scans, &poses, &error));
  EXPECT_NE(error.find("no_such_folder"), std::string::npos) << error;
}

}  // namespace
}  // namespace mlndt
