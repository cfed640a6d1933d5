// The localiser node's core against the library's LocalizeScans on the
// same map and clouds, map -> odom from the odometry's pose, and no jump on
// a result that is not to be used.
#include "integrations/ros/core/localizer_node_core.h"

#include <gtest/gtest.h>

#include "mlndt/common/pose.h"
#include "mlndt/grid/grid_io.h"
#include "tests/testing/kitti_bundle.h"
#include "tests/testing/run_tool.h"

namespace mlndt {
namespace ros_core {
namespace {

constexpr size_t kStride = 4;

// A map of the bundled KITTI frames 0-7 (every 4th point) on their
// reference poses, saved where the node loads it from.
std::string SaveKittiMap() {
  const std::vector<Isometry3d> poses = testing::BundledKittiPoses();
  PointCloud merged;
  for (int i = 0; i < 8; ++i) {
    const PointCloud scan = testing::BundledKittiScan(i, kStride);
    for (const Eigen::Vector3d& p : scan.points()) merged.Add(poses[i] * p);
  }
  LayeredGrid map;
  std::string error;
  EXPECT_TRUE(LayeredGrid::Build(LayeredGridOptions(), merged, &map, &error))
      << error;
  const std::string path =
      testing::FreshTestDir("localizer_node_core") + "/kitti.mlndt";
  EXPECT_TRUE(SaveLayeredGrid(path, map, &error)) << error;
  return path;
}

PointCloud2Scan KittiScan(int i) {
  PointCloud2Scan scan;
  scan.stamp_s = 100.0 + 0.1 * i;
  scan.frame_id = "velodyne";
  scan.cloud = testing::BundledKittiScan(i, kStride);
  return scan;
}

std::unique_ptr<LocalizerNodeCore> MakeCore(const std::string& odom_frame) {
  LocalizerNodeOptions options;
  options.map_path = SaveKittiMap();
  options.odom_frame = odom_frame;
  std::unique_ptr<LocalizerNodeCore> core;
  std::string error;
  EXPECT_TRUE(LocalizerNodeCore::Create(options, &core, &error)) << error;
  return core;
}

// An odometry's pose of frame i: the reference pose seen from a rotated,
// shifted odom frame.
Isometry3d OdomFromSensor(int i) {
  const Isometry3d odom_from_map = PoseVectorToIsometry(
      (Vector6d() << 3, -1, 0.2, 0.01, -0.02, 0.5).finished());
  return odom_from_map * testing::BundledKittiPoses()[i];
}

TEST(LocalizerNodeCore, PosesAreLocalizeScansAndMapToOdomFollows) {
  std::unique_ptr<LocalizerNodeCore> core = MakeCore("odom");
  ASSERT_NE(core, nullptr);
  const Isometry3d start = testing::BundledKittiPoses()[0];
  EXPECT_TRUE(core->Process(KittiScan(0), {}).waiting_for_initial_pose);
  core->SetInitialPose(start);

  std::vector<LocalizationResult> expected;
  std::string error;
  ASSERT_TRUE(LocalizeScans(
      core->options().localizer,
      core->map(),
      start,
      4,
      [](size_t i, PointCloud* cloud, std::string*) {
        *cloud = KittiScan(static_cast<int>(i)).cloud;
        return true;
      },
      nullptr,
      &expected,
      &error))
      << error;
  for (int i = 0; i < 4; ++i) {
    const LocalizerNodeOutput out =
        core->Process(KittiScan(i), {true, OdomFromSensor(i)});
    ASSERT_TRUE(out.processed);
    // The library's result read as the node reads it (scan_report.h).
    const ScanReport r =
        ReportOf(expected[static_cast<size_t>(i)], out.stamp_s);
    EXPECT_EQ(out.report.termination, r.termination) << i;
    ASSERT_TRUE(out.has_pose) << out.diagnostic.message;
    EXPECT_EQ(out.report.pose.matrix(), r.pose.matrix()) << i;
    EXPECT_EQ(out.covariance[0] > 0.0, true) << "a registration's covariance";
    ASSERT_TRUE(out.has_transform);
    EXPECT_TRUE(
        (out.map_from_child * OdomFromSensor(i)).isApprox(r.pose, 1e-12));
  }
}

// A scan of a flat floor only (translation along it unconstrained): the
// result is DEGENERATE, so no pose is published and map -> odom stays where
// the last usable scan put it.
TEST(LocalizerNodeCore, NoJumpOnAResultNotToBeUsed) {
  std::unique_ptr<LocalizerNodeCore> core = MakeCore("odom");
  ASSERT_NE(core, nullptr);
  core->SetInitialPose(testing::BundledKittiPoses()[0]);
  const LocalizerNodeOutput good =
      core->Process(KittiScan(0), {true, OdomFromSensor(0)});
  ASSERT_TRUE(good.has_pose) << good.diagnostic.message;

  PointCloud2Scan floor = KittiScan(1);
  floor.cloud = PointCloud();
  for (int a = -40; a <= 40; ++a) {
    for (int b = -40; b <= 40; ++b)
      floor.cloud.Add({0.25 * a, 0.25 * b, -1.73});
  }
  const LocalizerNodeOutput bad =
      core->Process(floor, {true, OdomFromSensor(1)});
  ASSERT_TRUE(bad.processed);
  EXPECT_EQ(bad.report.termination, TerminationType::DEGENERATE)
      << bad.diagnostic.message;
  EXPECT_FALSE(bad.has_pose);
  EXPECT_TRUE(bad.jump_refused);
  ASSERT_TRUE(bad.has_transform);
  EXPECT_EQ(bad.map_from_child.matrix(), good.map_from_child.matrix());
  EXPECT_EQ(bad.diagnostic.level, DiagnosticLevel::WARN);
  ASSERT_EQ(bad.warnings.size(), 1u);
  EXPECT_NE(bad.warnings[0].find("no jump: map -> odom kept"),
            std::string::npos)
      << bad.warnings[0];
}

// Without an odometry: map -> sensor; with one but no odom pose at the
// stamp: a warning and the last transform.
TEST(LocalizerNodeCore, WithoutOdometryAndWithoutItsPose) {
  std::unique_ptr<LocalizerNodeCore> alone = MakeCore("");
  ASSERT_NE(alone, nullptr);
  alone->SetInitialPose(testing::BundledKittiPoses()[0]);
  const LocalizerNodeOutput out = alone->Process(KittiScan(0), {});
  ASSERT_TRUE(out.has_pose);
  EXPECT_EQ(out.map_from_child.matrix(), out.report.pose.matrix());

  std::unique_ptr<LocalizerNodeCore> core = MakeCore("odom");
  core->SetInitialPose(testing::BundledKittiPoses()[0]);
  const LocalizerNodeOutput first = core->Process(KittiScan(0), {});
  EXPECT_TRUE(first.has_pose);
  EXPECT_FALSE(first.has_transform);
  ASSERT_EQ(first.warnings.size(), 1u);
  EXPECT_NE(first.warnings[0].find("no odom -> sensor on tf"),
            std::string::npos);
  // A repeated stamp is refused.
  const LocalizerNodeOutput repeat = core->Process(KittiScan(0), {});
  EXPECT_FALSE(repeat.processed);
  EXPECT_EQ(repeat.diagnostic.level, DiagnosticLevel::ERROR);
}

TEST(LocalizerNodeCore, RefusesAMissingMapAndAStartLayerBeyondIt) {
  LocalizerNodeOptions options;
  options.map_path = "/nonexistent/map.mlndt";
  std::unique_ptr<LocalizerNodeCore> core;
  std::string error;
  EXPECT_FALSE(LocalizerNodeCore::Create(options, &core, &error));
  EXPECT_NE(error.find("/nonexistent/map.mlndt"), std::string::npos) << error;
  options.map_path = SaveKittiMap();
  options.localizer.registration.schedule.start_layer = 16;
  options.start_layer_given = true;
  EXPECT_FALSE(LocalizerNodeCore::Create(options, &core, &error));
  EXPECT_NE(error.find("~start_layer=16 is out of range"), std::string::npos)
      << error;
}

}  // namespace
}  // namespace ros_core
}  // namespace mlndt
