// RunPoseGraph and its odometry factor on the bundled KITTI frames 0-3:
// the factor's residual scale and optimum, the pair weight against the
// odometry (KITTI's poses put frame 1 0.86 m ahead, the scans and the
// reference pairs 0.69 m: a tiny w follows the odometry, a large w the
// scans), extra pairs, and the option checks.

#include "lab/runs/pose_graph.h"

#include <ceres/ceres.h>
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "lab/eval/reference_pairs.h"
#include "mlndt/cloud/pose_io.h"
#include "mlndt/common/pose.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

using testing::BundledDataPath;

std::vector<std::string> KittiScans(int n) {
  std::vector<std::string> paths;
  for (int i = 0; i < n; ++i) {
    paths.push_back(
        BundledDataPath("kitti/pcd/00000" + std::to_string(i) + ".pcd"));
  }
  return paths;
}

std::vector<Isometry3d> KittiPoses(int n) {
  std::vector<Isometry3d> poses;
  std::string error;
  EXPECT_TRUE(
      ReadKittiPoses(BundledDataPath("kitti/poses_velo.txt"), &poses, &error))
      << error;
  poses.resize(n);
  return poses;
}

TEST(OdometryFactor, ResidualIsTheErrorOverSigmaAndItsOptimumTheMeasurement) {
  const Isometry3d measured = KittiPoses(2)[1];
  const OdometryNoise noise{0.05, 0.5};
  PoseBlocks first, second;
  ceres::Problem problem;
  const ceres::ResidualBlockId id =
      AddOdometryFactor(measured, noise, &first, &second, &problem);
  // 1 cm along x of scan 1 off the measurement: residual 0.01 / 0.05.
  Isometry3d off = measured;
  off.translation() += measured.linear() * Vector3d(0.01, 0.0, 0.0);
  second = PoseBlocks::From(off);
  double cost = 0.0;
  problem.EvaluateResidualBlock(id, false, &cost, nullptr, nullptr);
  EXPECT_NEAR(cost, 0.5 * 0.2 * 0.2, 1e-12);
  second = PoseBlocks();
  problem.SetParameterBlockConstant(first.rotation);
  problem.SetParameterBlockConstant(first.translation);
  ceres::Solver::Options options;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  const Isometry3d solved = second.ToIsometry();
  EXPECT_LT((solved.translation() - measured.translation()).norm(), 1e-8);
  EXPECT_LT(RotationErrorRad(solved, measured), 1e-8);
}

// Frame 1 relative to frame 0 in the joint result, against a target.
double Frame1ErrorM(const PoseGraphSummary& summary, const Isometry3d& target) {
  return ((summary.joint[0].inverse() * summary.joint[1]).translation() -
          target.translation())
      .norm();
}

TEST(RunPoseGraph, PairWeightMovesTheJointPosesFromTheOdometryToTheScans) {
  const std::vector<Isometry3d> odometry = KittiPoses(4);
  std::map<std::string, ReferencePair> pairs;
  std::string error;
  ASSERT_TRUE(ReadReferencePairs(
      BundledDataPath("kitti/reference_pairs.json"), &pairs, &error))
      << error;
  ASSERT_EQ(pairs.count("0_1"), 1u);
  const ReferencePair* reference = &pairs.at("0_1");
  // The two differ by 17 cm: the test can tell which one the graph follows.
  ASSERT_GT((odometry[1].translation() -
             reference->reference_from_input.translation())
                .norm(),
            0.15);
  PoseGraphOptions options;
  options.odometry = odometry;
  options.init_from_odometry = true;
  options.neighbors = 1;
  options.registration.num_threads = 2;
  PoseGraphSummary tiny, large;
  options.information_scale = 1e-6;
  ASSERT_TRUE(RunPoseGraph(options, KittiScans(4), &tiny, &error)) << error;
  options.information_scale = 1e3;
  ASSERT_TRUE(RunPoseGraph(options, KittiScans(4), &large, &error)) << error;
  EXPECT_FALSE(tiny.initial_is_chained);
  EXPECT_EQ(tiny.odometry_factors, 3);
  EXPECT_EQ(tiny.directed_pairs, 6);
  EXPECT_LT(Frame1ErrorM(tiny, odometry[1]), 0.01);
  EXPECT_LT(Frame1ErrorM(large, reference->reference_from_input), 0.03);
  EXPECT_LE(large.final_cost, large.cost_at_initial);
}

TEST(RunPoseGraph, ExtraPairsAddDirectedPairsAndBadOptionsAreRefused) {
  PoseGraphOptions options;
  options.neighbors = 1;
  options.extra_pairs = {{0, 2}};
  PoseGraphSummary summary;
  std::string error;
  ASSERT_TRUE(RunPoseGraph(options, KittiScans(3), &summary, &error)) << error;
  EXPECT_TRUE(summary.initial_is_chained);
  EXPECT_EQ(summary.directed_pairs, 6);  // 0-1, 1-2, 0-2, both ways.
  EXPECT_EQ(summary.joint.size(), 3u);
  EXPECT_EQ(summary.chained_failures, 0);

  options.extra_pairs = {{0, 3}};
  EXPECT_FALSE(RunPoseGraph(options, KittiScans(3), &summary, &error));
  EXPECT_EQ(error, "pair 0:3: scans are 0..2 and a pair needs two of them");
  options.extra_pairs.clear();
  options.init_from_odometry = true;
  EXPECT_FALSE(RunPoseGraph(options, KittiScans(3), &summary, &error));
  EXPECT_NE(error.find("needs odometry poses"), std::string::npos) << error;
  options.odometry = KittiPoses(2);
  EXPECT_FALSE(RunPoseGraph(options, KittiScans(3), &summary, &error));
  EXPECT_EQ(error, "odometry has 2 poses for 3 scans");
  options.odometry = KittiPoses(3);
  options.odometry_noise.sigma_deg = 0.0;
  EXPECT_FALSE(RunPoseGraph(options, KittiScans(3), &summary, &error));
  EXPECT_EQ(
      error,
      "invalid option: odometry_noise.sigma_deg = 0; it must be in [0.0001, "
      "180]");
  EXPECT_FALSE(RunPoseGraph(options, {KittiScans(1)}, &summary, &error));
  EXPECT_EQ(error, "fewer than 2 scans");
}

// The ranges come from PoseGraphOwnOptionsTable; the checks that need the
// number of scans stay.
TEST(PoseGraphOptions, IsValidTakesTheRangesFromTheTable) {
  std::string error;
  ASSERT_TRUE(PoseGraphOptions().IsValid(3, &error)) << error;
  const std::vector<
      std::pair<std::function<void(PoseGraphOptions*)>, std::string>>
      cases = {
          {[](PoseGraphOptions* o) { o->neighbors = 0; },
           "invalid option: neighbors = 0; it must be >= 1"},
          {[](PoseGraphOptions* o) { o->joint_layers = 3; },
           "invalid option: joint_layers = 3; it must be in [1, 2]"},
          {[](PoseGraphOptions* o) { o->max_iterations = 0; },
           "invalid option: max_iterations = 0; it must be >= 1"},
          {[](PoseGraphOptions* o) { o->information_scale = 2e3; },
           "invalid option: information_scale = 2000; it must be in (0, "
           "1000]"},
          {[](PoseGraphOptions* o) { o->odometry_noise.sigma_m = -1.0; },
           "invalid option: odometry_noise.sigma_m = -1; it must be in "
           "[0.0001, "
           "1000]"},
          // 1 / sigma^2 overflows (issue 41 item 3).
          {[](PoseGraphOptions* o) { o->odometry_noise.sigma_m = 1e-300; },
           "invalid option: odometry_noise.sigma_m = 1e-300; it must be in "
           "[0.0001, 1000]"},
          {[](PoseGraphOptions* o) {
             o->extra_pairs = {{1, 1}};
           },
           "pair 1:1: scans are 0..2 and a pair needs two of them"},
      };
  for (const auto& [spoil, message] : cases) {
    PoseGraphOptions options;
    spoil(&options);
    EXPECT_FALSE(options.IsValid(3, &error)) << message;
    EXPECT_EQ(error, message);
  }
}

// The odometry factors' gate: chi-square(6) at 99.9 % for all factors
// together (issue 41 item 3).
TEST(OdometryChi2Gate, IsTheBonferroniQuantileOfChiSquareSix) {
  EXPECT_NEAR(OdometryChi2Gate(1), 22.458, 0.01);
  EXPECT_NEAR(OdometryChi2Gate(7), 27.03, 0.01);
  EXPECT_NEAR(OdometryChi2Gate(249), 35.16, 0.01);
  EXPECT_NEAR(OdometryChi2Gate(0), OdometryChi2Gate(1), 1e-12);
}

}  // namespace
}  // namespace mlndt
