// The odometry node's core against the library's run over the same clouds:
// the same poses bit for bit, and clouds it cannot use refused with a
// warning without changing the poses of the others.
#include "integrations/ros/core/odometry_node_core.h"

#include <gtest/gtest.h>

#include "mlndt/odometry/run_odometry.h"
#include "tests/testing/kitti_bundle.h"

namespace mlndt {
namespace ros_core {
namespace {

// Bundled KITTI frame i (every 4th point) at stamp 0.1 i with a per-point
// time ramp, so the odometry deskews.
PointCloud2Scan KittiScan(int i) {
  PointCloud2Scan scan;
  scan.stamp_s = 0.1 * i;
  scan.frame_id = "velodyne";
  scan.cloud = testing::BundledKittiScan(i, 4);
  for (size_t k = 0; k < scan.cloud.size(); ++k) {
    scan.point_times_s.push_back(-0.05 + 0.1 * k / scan.cloud.size());
  }
  scan.time_field = "time";
  return scan;
}

std::vector<OdometryResult> LibraryRun(const OdometryOptions& options,
                                       const std::vector<int>& frames) {
  std::vector<OdometryResult> results;
  OdometrySummary summary;
  std::string error;
  const OdometryScanLoader load = [&](size_t k,
                                      PointCloud* cloud,
                                      std::vector<double>* times,
                                      double* stamp_s,
                                      std::string*) {
    const PointCloud2Scan scan = KittiScan(frames[k]);
    *cloud = scan.cloud;
    *times = scan.point_times_s;
    *stamp_s = scan.stamp_s;
    return true;
  };
  EXPECT_TRUE(RunOdometry(
      options, frames.size(), load, nullptr, &results, &summary, &error))
      << error;
  return results;
}

bool Mentions(const std::vector<std::string>& warnings,
              const std::string& text) {
  for (const std::string& w : warnings) {
    if (w.find(text) != std::string::npos) return true;
  }
  return false;
}

// Frames 0, 1, 1 again (a repeated stamp), an empty cloud, 2, then 4 (3
// dropped): the node refuses the repeat and the empty cloud with warnings,
// notes the gap, and its poses are the library's over 0, 1, 2, 4 bit for
// bit.
TEST(OdometryNodeCore, PosesAreTheLibrarysAndBadCloudsAreRefused) {
  OdometryNodeOptions options;
  options.node.local_map_period_s = 0.15;
  const std::vector<OdometryResult> expected =
      LibraryRun(options.odometry, {0, 1, 2, 4});
  ASSERT_EQ(expected.size(), 4u);

  PointCloud2Scan empty;
  empty.stamp_s = 0.15;
  empty.frame_id = "velodyne";
  const std::vector<PointCloud2Scan> clouds = {KittiScan(0),
                                               KittiScan(1),
                                               KittiScan(1),
                                               empty,
                                               KittiScan(2),
                                               KittiScan(4)};
  OdometryNodeCore core(options);
  std::vector<OdometryNodeOutput> outputs;
  for (const PointCloud2Scan& cloud : clouds) {
    outputs.push_back(core.Process(cloud));
  }
  const std::vector<bool> has_pose = {true, true, false, false, true, true};
  size_t k = 0;
  for (size_t i = 0; i < outputs.size(); ++i) {
    const OdometryNodeOutput& out = outputs[i];
    ASSERT_EQ(out.has_pose, has_pose[i]) << i;
    EXPECT_EQ(out.frame_id, "velodyne");
    if (!out.has_pose) {
      EXPECT_EQ(out.diagnostic.level, DiagnosticLevel::ERROR) << i;
      continue;
    }
    // The library's result read as the node reads it (scan_report.h).
    const ScanReport r = ReportOf(expected[k++]);
    EXPECT_EQ(out.report.pose.matrix(), r.pose.matrix()) << i;
    EXPECT_EQ(out.report.stamp_s, r.stamp_s);
    EXPECT_EQ(out.report.termination, r.termination);
    EXPECT_EQ(out.report.registered, r.registered);
    EXPECT_EQ(out.report.deskewed, r.deskewed);
  }
  EXPECT_TRUE(outputs[5].report.deskewed);  // Once the motion is known.
  EXPECT_TRUE(Mentions(outputs[2].warnings, "not after the last scan's"));
  EXPECT_TRUE(Mentions(outputs[3].warnings, "no finite points"));
  EXPECT_TRUE(Mentions(outputs[5].warnings, "gap of 0.200000 s"));
  EXPECT_TRUE(outputs[4].warnings.empty());
  EXPECT_EQ(core.num_used(), 4u);
  // The local map at the first scan, then every 0.15 s of scan time.
  EXPECT_TRUE(outputs[0].local_map_due);
  EXPECT_FALSE(outputs[1].local_map_due);
  EXPECT_TRUE(outputs[4].local_map_due);
  EXPECT_TRUE(outputs[5].local_map_due);
  EXPECT_GT(outputs[0].local_map_points.size(), 100u);
}

// A message it cannot decode is refused, and the next one is used.
TEST(OdometryNodeCore, MalformedMessageIsRefused) {
  OdometryNodeCore core{OdometryNodeOptions()};
  PointCloud2View no_z;
  no_z.stamp_s = 5.0;
  no_z.fields = {{"x", 0, kPointFieldFloat32}, {"y", 4, kPointFieldFloat32}};
  no_z.point_step = 8;
  const OdometryNodeOutput out = core.ProcessMessage(no_z);
  EXPECT_FALSE(out.has_pose);
  EXPECT_TRUE(Mentions(out.warnings, "malformed: no float32/float64 x, y"));
  EXPECT_EQ(out.diagnostic.values.back().second, "REFUSED");
  EXPECT_TRUE(core.Process(KittiScan(0)).has_pose);
}

}  // namespace
}  // namespace ros_core
}  // namespace mlndt
