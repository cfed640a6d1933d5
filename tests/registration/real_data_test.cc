// Registration on the real scans bundled in data/: the Velodyne pair used by
// ndt_omp / fast_gicp / small_gicp, and KITTI 00 frames 0-7 with ground truth.

#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include "mlndt/cloud/pose_io.h"
#include "mlndt/common/pose.h"
#include "mlndt/registration/registration.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

class KittiFrames : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    for (int i = 0; i < 8; ++i) {
      scans_.push_back(testing::LoadBundledCloud("kitti/pcd/00000" +
                                                 std::to_string(i) + ".pcd"));
    }
    std::string error;
    ASSERT_TRUE(ReadKittiPoses(
        testing::BundledDataPath("kitti/poses_velo.txt"), &poses_, &error))
        << error;
    ASSERT_EQ(poses_.size(), 8u);
  }
  static Isometry3d Truth(int i, int j) {
    return poses_[i].inverse() * poses_[j];
  }
  static RegistrationSummary Align(int i, int j, const Isometry3d& initial) {
    RegistrationSummary summary;
    Register(RegistrationOptions(), scans_[i], scans_[j], initial, &summary);
    return summary;
  }
  static std::vector<PointCloud> scans_;
  static std::vector<Isometry3d> poses_;
};
std::vector<PointCloud> KittiFrames::scans_;
std::vector<Isometry3d> KittiFrames::poses_;

TEST(VelodynePair, MatchesReferenceResultFromIdentity) {
  // small_gicp's T_target_source: 5 cm and 0.5 deg, as fast_gicp's own test.
  const PointCloud target = testing::LoadBundledCloud("koide3/251370668.pcd");
  const PointCloud source = testing::LoadBundledCloud("koide3/251371071.pcd");
  Isometry3d expected;
  std::string error;
  std::vector<Isometry3d> unused;
  RegistrationSummary summary;
  Register(
      RegistrationOptions(), target, source, Isometry3d::Identity(), &summary);
  ASSERT_TRUE(summary.IsSolutionUsable()) << summary.message;
  Eigen::Matrix4d m;
  m << 0.999925, 0.0121483, -0.00177009, 0.488882,   //
      -0.0121523, 0.999924, -0.00228657, 0.121214,   //
      0.00174218, 0.00230791, 0.999996, -0.0253342,  //
      0, 0, 0, 1;
  expected.matrix() = m;
  EXPECT_LT(TranslationErrorM(expected, summary.reference_from_input), 0.05)
      << summary.FullReport();
  EXPECT_LT(
      RotationErrorRad(expected, summary.reference_from_input) * kRadToDeg, 0.5)
      << summary.FullReport();
  // The report shows the verdict's evidence.
  char fit[96];
  std::snprintf(fit,
                sizeof(fit),
                "  fit:            median distance %.3f, inliers %.3f, mean "
                "score %.3f",
                summary.quality.median_distance,
                summary.quality.inlier_fraction,
                summary.quality.mean_score);
  EXPECT_GT(summary.quality.inlier_fraction, 0.5);
  EXPECT_LT(summary.quality.median_distance,
            QualityCheckOptions().max_median_distance);
  EXPECT_NE(summary.FullReport().find(fit), std::string::npos)
      << summary.FullReport();
}

TEST_F(KittiFrames, ConsecutivePairsFromIdentityMatchGroundTruth) {
  for (int i = 0; i + 1 < 8; ++i) {
    const RegistrationSummary s = Align(i, i + 1, Isometry3d::Identity());
    ASSERT_TRUE(s.IsSolutionUsable()) << s.message;
    EXPECT_LT(TranslationErrorM(Truth(i, i + 1), s.reference_from_input), 0.2)
        << "pair " << i << "-" << i + 1 << "\n"
        << s.FullReport();
    EXPECT_LT(
        RotationErrorRad(Truth(i, i + 1), s.reference_from_input) * kRadToDeg,
        1.0)
        << "pair " << i << "-" << i + 1;
  }
}

TEST_F(KittiFrames, WiderPairsFromIdentityAgreeWithChainedConsecutivePairs) {
  // Frames 2, 3 and 5 apart: rotation within 1 deg of ground truth, and the
  // direct estimate agrees with the chain of consecutive estimates. (Against
  // the translation of the ground truth these scans fit best at ~0.8 of it,
  // see README "Ground truth of the KITTI frames"; so the chain is the check.)
  std::vector<Isometry3d> consecutive;
  for (int i = 0; i + 1 < 8; ++i) {
    const RegistrationSummary s = Align(i, i + 1, Isometry3d::Identity());
    ASSERT_TRUE(s.IsSolutionUsable()) << s.message;
    consecutive.push_back(s.reference_from_input);
  }
  for (int gap : {2, 3, 5}) {
    for (int i = 0; i + gap < 8; ++i) {
      Isometry3d chained = Isometry3d::Identity();
      for (int k = i; k < i + gap; ++k)
        chained = chained * consecutive[static_cast<size_t>(k)];
      const RegistrationSummary s = Align(i, i + gap, Isometry3d::Identity());
      ASSERT_TRUE(s.IsSolutionUsable()) << s.message;
      EXPECT_LT(RotationErrorRad(Truth(i, i + gap), s.reference_from_input) *
                    kRadToDeg,
                1.0)
          << "pair " << i << "-" << i + gap;
      EXPECT_LT(TranslationErrorM(chained, s.reference_from_input), 0.1 * gap)
          << "pair " << i << "-" << i + gap << "\n"
          << s.FullReport();
      EXPECT_LT(RotationErrorRad(chained, s.reference_from_input) * kRadToDeg,
                0.5)
          << "pair " << i << "-" << i + gap;
    }
  }
}

TEST_F(KittiFrames, LongRangeStartsConverge) {
  // The paper's long-range claim: ground truth pushed off by 5 m, 10 m,
  // 30 and 45 deg of yaw, and (3 m, 3 m, 20 deg); at least 90 % within
  // 0.2 m and 1 deg on consecutive pairs.
  const std::vector<Vector6d> offsets = {
      PoseVectorFromDegrees(5, 0, 0, 0, 0, 0),
      PoseVectorFromDegrees(10, 0, 0, 0, 0, 0),
      PoseVectorFromDegrees(0, 0, 0, 0, 0, 30),
      PoseVectorFromDegrees(0, 0, 0, 0, 0, 45),
      PoseVectorFromDegrees(3, 3, 0, 0, 0, 20)};
  int runs = 0, successes = 0;
  for (int i = 0; i + 1 < 8; ++i) {
    for (const Vector6d& offset : offsets) {
      const Isometry3d truth = Truth(i, i + 1);
      const RegistrationSummary s =
          Align(i, i + 1, PoseVectorToIsometry(offset) * truth);
      ++runs;
      successes +=
          s.IsSolutionUsable() &&
          TranslationErrorM(truth, s.reference_from_input) < 0.2 &&
          RotationErrorRad(truth, s.reference_from_input) * kRadToDeg < 1.0;
    }
  }
  EXPECT_GE(successes, (runs * 9 + 9) / 10) << successes << " of " << runs;
}

}  // namespace
}  // namespace mlndt
