// ComputeOdometryMetrics on the bundled KITTI trajectory (data/kitti,
// frames 0-7) given in another world frame: the exact odometry (poses from
// the first scan) has no error and an identity alignment (the reference is
// re-based on its first pose); an odometry with known per-pose errors has
// the RPE computed here from its definition, over a delta clamped to the
// trajectory; short or missing references are refused.

#include "lab/eval/odometry_metrics.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lab/eval/trajectory_io.h"
#include "mlndt/common/pose.h"
#include "tests/testing/kitti_bundle.h"

namespace mlndt {
namespace {

// The KITTI poses in a world frame moved by 10 m and 30 deg.
std::vector<Isometry3d> Reference() {
  const Isometry3d world = PoseVectorToIsometry(
      PoseVectorFromDegrees(10.0, -4.0, 1.0, 2.0, -3.0, 30.0));
  std::vector<Isometry3d> poses;
  for (const Isometry3d& pose : testing::BundledKittiPoses()) {
    poses.push_back(world * pose);
  }
  return poses;
}

// Odometry from the first scan, pose k off by (k cm, 0.1 k deg of yaw).
std::vector<OdometryResult> Odometry(const std::vector<Isometry3d>& reference,
                                     bool with_errors) {
  std::vector<OdometryResult> results;
  for (size_t k = 0; k < reference.size(); ++k) {
    OdometryResult r;
    r.world_from_sensor = reference[0].inverse() * reference[k];
    if (with_errors) {
      r.world_from_sensor =
          r.world_from_sensor * PoseVectorToIsometry(PoseVectorFromDegrees(
                                    0.01 * k, 0.0, 0.0, 0.0, 0.0, 0.1 * k));
    }
    results.push_back(r);
  }
  return results;
}

TEST(ComputeOdometryMetrics, ExactOdometryHasNoErrorInTheFirstScansFrame) {
  const std::vector<Isometry3d> reference = Reference();
  ASSERT_EQ(reference.size(), 8u);
  OdometryMetrics metrics;
  std::string error;
  ASSERT_TRUE(ComputeOdometryMetrics(
      reference, Odometry(reference, false), 1, {1.0, 2.0}, &metrics, &error))
      << error;
  EXPECT_NEAR(metrics.ate.rmse_m, 0.0, 1e-9);
  EXPECT_NEAR(metrics.rpe.translation_m.max, 0.0, 1e-9);
  EXPECT_NEAR(metrics.segments.translation_error_percent, 0.0, 1e-7);
  ASSERT_FALSE(metrics.segments.segments.empty());  // The scans span ~6 m.
  // Re-based on the first pose: no world change is left to align.
  EXPECT_NEAR(
      metrics.ate.reference_from_estimate.translation.norm(), 0.0, 1e-6);
  EXPECT_NEAR(
      (metrics.ate.reference_from_estimate.rotation - Matrix3d::Identity())
          .norm(),
      0.0,
      1e-6);
}

TEST(ComputeOdometryMetrics, RpeMatchesItsDefinitionOverAClampedDelta) {
  const std::vector<Isometry3d> reference = Reference();
  const std::vector<OdometryResult> results = Odometry(reference, true);
  OdometryMetrics metrics;
  std::string error;
  // delta 100 on 8 poses: the RPE of scans 0 and 7, the only pair.
  ASSERT_TRUE(
      ComputeOdometryMetrics(reference, results, 100, {1.0}, &metrics, &error))
      << error;
  EXPECT_EQ(metrics.rpe_delta, 7);  // Used (issue 41 item 14).
  EXPECT_EQ(metrics.rpe_delta_asked, 100);
  ASSERT_EQ(metrics.rpe.translation_m.count, 1u);
  const Isometry3d q = reference[0].inverse() * reference[7];
  const Isometry3d p =
      results[0].world_from_sensor.inverse() * results[7].world_from_sensor;
  EXPECT_NEAR(metrics.rpe.translation_m.mean,
              (q.translation() - p.translation()).norm(),
              1e-9);
  EXPECT_GT(metrics.ate.rmse_m, 0.01);
}

TEST(ComputeOdometryMetrics, RefusesAReferenceShorterThanTheScans) {
  const std::vector<Isometry3d> reference = Reference();
  std::vector<OdometryResult> results = Odometry(reference, false);
  results.push_back(results.back());
  OdometryMetrics metrics;
  std::string error;
  EXPECT_FALSE(
      ComputeOdometryMetrics(reference, results, 1, {1.0}, &metrics, &error));
  EXPECT_EQ(error,
            "the reference has 8 pose(s) for 9 scan(s): it needs one "
            "per scan");
  EXPECT_FALSE(
      ComputeOdometryMetrics(reference, {}, 1, {1.0}, &metrics, &error));
}

}  // namespace
}  // namespace mlndt
