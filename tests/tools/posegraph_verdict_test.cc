// mlndt_posegraph judges its joint result (issue 41 item 3): from an
// odometry with one pose 5 m off, or drifting 3 deg a scan in yaw, the
// joint trajectory is wrong, and the run ends LOW_QUALITY with exit 1 (it
// was CONVERGENCE with exit 0); from KITTI's own poses it ends CONVERGENCE
// with exit 0. Odometry noise sigmas below 1e-4 are refused (exit 2): 1e-300
// gave a cost of inf, 0 iterations and "CONVERGENCE".

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "mlndt/cloud/pose_io.h"
#include "mlndt/common/pose.h"
#include "tests/testing/run_tool.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

using testing::RunTool;
using testing::ToolRun;
const auto& Quote = testing::ShellQuote;

std::vector<Isometry3d> KittiPoses() {
  std::vector<Isometry3d> poses;
  std::string error;
  EXPECT_TRUE(ReadKittiPoses(
      testing::BundledDataPath("kitti/poses_velo.txt"), &poses, &error))
      << error;
  return poses;
}

std::string WritePoses(const std::string& path,
                       const std::vector<Isometry3d>& poses) {
  std::string error;
  EXPECT_TRUE(WriteKittiPoses(path, poses, &error)) << error;
  return path;
}

ToolRun RunFromOdometry(const std::string& odometry,
                        const std::string& extra = "") {
  return RunTool("mlndt_posegraph",
                 "--scans=" + Quote(testing::BundledDataPath("kitti/pcd")) +
                     " --gt_poses=" +
                     Quote(testing::BundledDataPath("kitti/poses_velo.txt")) +
                     " --odometry_poses=" + Quote(odometry) +
                     " --init=odometry " + extra,
                 300);
}

TEST(PosegraphVerdict, KittiOwnPosesAsOdometryConverge) {
  const ToolRun run =
      RunFromOdometry(testing::BundledDataPath("kitti/poses_velo.txt"));
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("\"verdict\": \"CONVERGENCE\""), std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("\"pair_checks\""), std::string::npos);
}

TEST(PosegraphVerdict, OnePoseFiveMetresOffIsLowQuality) {
  const std::string dir = testing::FreshTestDir("posegraph_verdict");
  std::vector<Isometry3d> poses = KittiPoses();
  ASSERT_EQ(poses.size(), 8u);
  poses[4].translation().x() += 5.0;
  const ToolRun run = RunFromOdometry(WritePoses(dir + "/odometry.txt", poses),
                                      "--output_dir=" + Quote(dir + "/out"));
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_NE(run.out.find("\"verdict\": \"LOW_QUALITY\""), std::string::npos)
      << run.out;
  EXPECT_NE(run.err.find("pair 3:4"), std::string::npos) << run.err;
  // Every file is still written.
  std::vector<Isometry3d> joint;
  std::string error;
  EXPECT_TRUE(ReadKittiPoses(dir + "/out/trajectory_joint.txt", &joint, &error))
      << error;
  EXPECT_EQ(joint.size(), 8u);
}

TEST(PosegraphVerdict, YawDriftOfThreeDegreesAScanIsLowQuality) {
  const std::string dir = testing::FreshTestDir("posegraph_verdict");
  const std::vector<Isometry3d> truth = KittiPoses();
  ASSERT_EQ(truth.size(), 8u);
  std::vector<Isometry3d> drifting = {truth[0]};
  const Isometry3d yaw(Eigen::AngleAxisd(3.0 * kDegToRad, Vector3d::UnitZ()));
  for (size_t i = 1; i < truth.size(); ++i) {
    drifting.push_back(drifting.back() * yaw *
                       (truth[i - 1].inverse() * truth[i]));
  }
  const ToolRun run =
      RunFromOdometry(WritePoses(dir + "/odometry.txt", drifting));
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_NE(run.out.find("\"verdict\": \"LOW_QUALITY\""), std::string::npos)
      << run.out;
  EXPECT_NE(run.err.find("from the pair's own optimum"), std::string::npos)
      << run.err;
}

TEST(PosegraphVerdict, OdometrySigmasHaveALowerBound) {
  const std::string odometry = testing::BundledDataPath("kitti/poses_velo.txt");
  for (const std::string flag : {"--odometry_noise_sigma_m=1e-300",
                                 "--odometry_noise_sigma_deg=1e-300",
                                 "--odometry_noise_sigma_m=0.00005"}) {
    SCOPED_TRACE(flag);
    const ToolRun run = RunFromOdometry(odometry, flag);
    EXPECT_EQ(run.exit_code, 2) << run.err;
    EXPECT_NE(run.err.find(flag.substr(2, flag.find('=') - 2)),
              std::string::npos)
        << run.err;
    EXPECT_EQ(run.out, "");
  }
  const ToolRun at_bound =
      RunFromOdometry(odometry, "--odometry_noise_sigma_m=0.0001");
  EXPECT_NE(at_bound.exit_code, 2) << at_bound.err;
}

}  // namespace
}  // namespace mlndt
