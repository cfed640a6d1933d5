// Rendering scans: the range noise has the sensor's sigma, dropouts their
// rate, and with motion within the scan DeskewScan with the trajectory's
// velocity moves every point onto the exact surface in the stamp's frame.

#include "lab/sim/scan_renderer.h"

#include <gtest/gtest.h>

#include <cmath>

#include "lab/sim/mesh_shapes.h"
#include "lab/sim/sim_trajectory.h"
#include "mlndt/odometry/deskew.h"

namespace mlndt {
namespace sim {
namespace {

// A closed box room, 40 x 30 x 8 m.
std::unique_ptr<RayCaster> Room() {
  TriangleMesh mesh;
  AddBox(Vector3d(-20, -15, -2), Vector3d(20, 15, 6), &mesh);
  std::string error;
  auto caster = RayCaster::Create(mesh, &error);
  EXPECT_NE(caster, nullptr) << error;
  return caster;
}

TEST(RenderScan, NoiseAndDropoutsFollowTheReturnModel) {
  const auto caster = Room();
  SensorModel sensor;
  ASSERT_TRUE(MakeSensorModel("os1_64", &sensor));
  sensor.returns.range_sigma_m = 0.03;
  sensor.returns.dropout_probability = 0.1;
  sensor.returns.min_cos_incidence = 0.0;
  ScanMotion motion;
  motion.world_from_sensor =
      PoseFromYawPitchRoll(Vector3d(1, 2, 0.5), 0.3, 0.05, -0.02);
  SimScan scan;
  RenderScan(*caster, sensor, SensorRays(sensor, 0.0), motion, 42, &scan);
  ASSERT_EQ(scan.rays, 65536u);
  // Every ray hits the closed room; 10 % dropped.
  EXPECT_NEAR(static_cast<double>(scan.points.size()) / scan.rays, 0.9, 0.01);
  double sum = 0, sum2 = 0;
  for (size_t k = 0; k < scan.points.size(); ++k) {
    const double exact =
        (motion.world_from_sensor.inverse() * scan.world_hits[k]).norm();
    const double error = scan.points[k].norm() - exact;
    sum += error;
    sum2 += error * error;
  }
  const double n = static_cast<double>(scan.points.size());
  EXPECT_NEAR(sum / n, 0.0, 0.001);
  EXPECT_NEAR(std::sqrt(sum2 / n), 0.03, 0.001);
  // The same seed, the same scan; another seed, other noise.
  SimScan again, other;
  RenderScan(*caster, sensor, SensorRays(sensor, 0.0), motion, 42, &again);
  RenderScan(*caster, sensor, SensorRays(sensor, 0.0), motion, 43, &other);
  EXPECT_EQ(again.points, scan.points);
  EXPECT_NE(other.points, scan.points);
}

TEST(RenderScan, MotionWithinTheScanIsUndoneByDeskewing) {
  const auto caster = Room();
  SensorModel sensor;
  ASSERT_TRUE(MakeSensorModel("vlp16", &sensor));
  sensor.returns.range_sigma_m = 0.0;
  sensor.returns.dropout_probability = 0.0;
  SimTrajectory trajectory;
  trajectory.world_from_sensor = {
      PoseFromYawPitchRoll(Vector3d(0, 0, 0), 0.0, 0.0, 0.0),
      PoseFromYawPitchRoll(Vector3d(1.5, 0.3, 0.05), 0.1, 0.01, 0.0)};
  trajectory.stamps_s = {0.0, 0.1};  // 15 m/s, 57 deg/s.
  ScanMotion motion;
  motion.world_from_sensor = trajectory.world_from_sensor[0];
  motion.velocity = trajectory.Velocity(0);
  motion.moving = true;
  SimScan scan;
  RenderScan(*caster, sensor, SensorRays(sensor, 0.0), motion, 1, &scan);
  PointCloud cloud(scan.points);
  const std::vector<double> times(scan.times_s.begin(), scan.times_s.end());
  double skew = 0.0;
  for (size_t k = 0; k < cloud.size(); ++k) {
    skew = std::max(
        skew,
        (cloud[k] - motion.world_from_sensor.inverse() * scan.world_hits[k])
            .norm());
  }
  EXPECT_GT(skew, 1.0);  // The points are skewed by the motion.
  std::string error;
  ASSERT_TRUE(DeskewScan(motion.velocity, times, &cloud, &error)) << error;
  for (size_t k = 0; k < cloud.size(); ++k) {
    ASSERT_NEAR(
        (cloud[k] - motion.world_from_sensor.inverse() * scan.world_hits[k])
            .norm(),
        0.0,
        1e-4)
        << k;
  }
  // The last scan moves as the one before.
  EXPECT_EQ(trajectory.Velocity(1), trajectory.Velocity(0));
}

}  // namespace
}  // namespace sim
}  // namespace mlndt
