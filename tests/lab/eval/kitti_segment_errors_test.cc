#include "lab/eval/kitti_segment_errors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "mlndt/common/pose.h"

namespace mlndt {
namespace {

constexpr double kStepM = 0.1;  // Between frames.

// Frames every kStepM metres along x, `length_m` in all.
std::vector<Isometry3d> StraightLine(double length_m) {
  std::vector<Isometry3d> poses;
  const int n = static_cast<int>(std::lround(length_m / kStepM)) + 1;
  for (int k = 0; k < n; ++k) {
    Isometry3d pose = Isometry3d::Identity();
    pose.translation().x() = k * kStepM;
    poses.push_back(pose);
  }
  return poses;
}

TEST(ComputeKittiSegmentErrors, OnePercentScaleDriftIsOnePercentEverywhere) {
  const std::vector<Isometry3d> truth = StraightLine(1000.0);
  std::vector<Isometry3d> estimate = truth;
  for (Isometry3d& pose : estimate) pose.translation() *= 1.01;
  KittiSegmentSummary summary;
  std::string error;
  ASSERT_TRUE(ComputeKittiSegmentErrors(
      KittiSegmentOptions(), truth, estimate, &summary, &error))
      << error;
  ASSERT_EQ(summary.lengths.size(), 8u);
  for (size_t i = 0; i < summary.lengths.size(); ++i) {
    const KittiLengthErrors& row = summary.lengths[i];
    EXPECT_EQ(row.length_m, 100.0 * (i + 1));
    // The last frame overshoots the length by up to one 0.1 m step, and the
    // devkit divides by the length: 1 % x (L + 0.1) / L.
    EXPECT_NEAR(row.translation_error_percent, 1.0, 0.0011) << row.length_m;
    EXPECT_NEAR(row.rotation_error_deg_per_m, 0.0, 1e-9) << row.length_m;
    // First frames every 10 frames (1 m) that still have L metres ahead.
    EXPECT_NEAR(row.num_segments, 1000.0 - row.length_m, 1.0) << row.length_m;
  }
  EXPECT_NEAR(summary.translation_error_percent, 1.0, 0.0011);
  EXPECT_NEAR(summary.rotation_error_deg_per_m, 0.0, 1e-9);
  // Segments in the devkit's units (m/m) and frame order.
  ASSERT_FALSE(summary.segments.empty());
  EXPECT_EQ(summary.segments[0].first_frame, 0u);
  EXPECT_EQ(summary.segments[0].length_m, 100.0);
  EXPECT_NEAR(summary.segments[0].translation_error, 0.01, 1.1e-5);
  EXPECT_EQ(summary.segments[8].first_frame, 10u);
}

TEST(ComputeKittiSegmentErrors, LengthsBeyondTheTrajectoryAreAbsent) {
  const std::vector<Isometry3d> truth = StraightLine(350.0);
  KittiSegmentSummary summary;
  std::string error;
  ASSERT_TRUE(ComputeKittiSegmentErrors(
      KittiSegmentOptions(), truth, truth, &summary, &error))
      << error;
  ASSERT_EQ(summary.lengths.size(), 3u);
  EXPECT_EQ(summary.lengths[0].length_m, 100.0);
  EXPECT_EQ(summary.lengths[2].length_m, 300.0);
  EXPECT_NEAR(summary.translation_error_percent, 0.0, 1e-12);  // Perfect.

  // Shorter than every length: no segments, means NaN (not 0).
  ASSERT_TRUE(ComputeKittiSegmentErrors(KittiSegmentOptions(),
                                        StraightLine(99.0),
                                        StraightLine(99.0),
                                        &summary,
                                        &error));
  EXPECT_TRUE(summary.lengths.empty());
  EXPECT_TRUE(summary.segments.empty());
  EXPECT_TRUE(std::isnan(summary.translation_error_percent));
  EXPECT_TRUE(std::isnan(summary.rotation_error_deg_per_m));
}

TEST(ComputeKittiSegmentErrors, YawDriftPerMetreIsTheRotationError) {
  const double drift_deg_per_m = 0.01;
  const std::vector<Isometry3d> truth = StraightLine(900.0);
  // The estimate turns by drift x step about z at every step.
  std::vector<Isometry3d> estimate = {Isometry3d::Identity()};
  const Isometry3d step = PoseVectorToIsometry(
      PoseVectorFromDegrees(kStepM, 0, 0, 0, 0, drift_deg_per_m * kStepM));
  while (estimate.size() < truth.size())
    estimate.push_back(estimate.back() * step);
  KittiSegmentSummary summary;
  std::string error;
  ASSERT_TRUE(ComputeKittiSegmentErrors(
      KittiSegmentOptions(), truth, estimate, &summary, &error))
      << error;
  ASSERT_EQ(summary.lengths.size(), 8u);
  for (const KittiLengthErrors& row : summary.lengths) {
    // Overshoot up to 0.1 m of L: (L + 0.1) / L.
    EXPECT_NEAR(row.rotation_error_deg_per_m,
                drift_deg_per_m,
                drift_deg_per_m * 0.1 / row.length_m + 1e-9)
        << row.length_m;
    EXPECT_GT(row.translation_error_percent, 0.0);  // The path bends.
  }
  EXPECT_NEAR(summary.rotation_error_deg_per_m, drift_deg_per_m, 2e-5);
}

// The last frame is the first one whose distance exceeds first + L: with
// exact 1 m steps, frame 100 is exactly 100 m from frame 0 and does not
// count (the devkit compares with '>').
TEST(ComputeKittiSegmentErrors, LastFrameIsTheFirstBeyondTheLength) {
  std::vector<Isometry3d> truth;
  for (int k = 0; k <= 250; ++k) {
    Isometry3d pose = Isometry3d::Identity();
    pose.translation().x() = k;
    truth.push_back(pose);
  }
  KittiSegmentOptions options;
  options.lengths_m = {100, 200};
  KittiSegmentSummary summary;
  std::string error;
  ASSERT_TRUE(
      ComputeKittiSegmentErrors(options, truth, truth, &summary, &error));
  ASSERT_GE(summary.segments.size(), 2u);
  EXPECT_EQ(summary.segments[0].last_frame, 101u);
  EXPECT_EQ(summary.segments[1].last_frame, 201u);
  // First frames 0, 10, ..., 140 reach 100 m (149 < 250); 0..40 reach 200 m.
  ASSERT_EQ(summary.lengths.size(), 2u);
  EXPECT_EQ(summary.lengths[0].num_segments, 15u);
  EXPECT_EQ(summary.lengths[1].num_segments, 5u);
}

// A direct transcription of the devkit's calcSequenceErrors (linear search
// for the last frame, E = R^-1 G, angle from the trace) on a random walk.
TEST(ComputeKittiSegmentErrors, MatchesTheDevkitLoopOnARandomWalk) {
  std::mt19937 rng(21);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<Isometry3d> truth = {Isometry3d::Identity()};
  std::vector<Isometry3d> estimate = {Isometry3d::Identity()};
  for (int k = 1; k < 1500; ++k) {
    const Vector6d xi = PoseVectorFromDegrees(
        1.0, 0.1 * normal(rng), 0.02 * normal(rng), 0, 0, normal(rng));
    const Vector6d noise = PoseVectorFromDegrees(0.01 * normal(rng),
                                                 0.01 * normal(rng),
                                                 0.01 * normal(rng),
                                                 0.05 * normal(rng),
                                                 0.05 * normal(rng),
                                                 0.05 * normal(rng));
    truth.push_back(truth.back() * PoseVectorToIsometry(xi));
    estimate.push_back(estimate.back() * PoseVectorToIsometry(xi) *
                       PoseVectorToIsometry(noise));
  }
  KittiSegmentSummary summary;
  std::string error;
  ASSERT_TRUE(ComputeKittiSegmentErrors(
      KittiSegmentOptions(), truth, estimate, &summary, &error))
      << error;

  std::vector<double> dist = {0.0};
  for (size_t i = 1; i < truth.size(); ++i) {
    dist.push_back(
        dist.back() +
        (truth[i].translation() - truth[i - 1].translation()).norm());
  }
  const double lengths[] = {100, 200, 300, 400, 500, 600, 700, 800};
  size_t s = 0;
  double t_sum = 0.0, r_sum = 0.0;
  for (size_t first = 0; first < truth.size(); first += 10) {
    for (double len : lengths) {
      int last = -1;
      for (size_t i = first; i < dist.size(); ++i) {
        if (dist[i] > dist[first] + len) {
          last = static_cast<int>(i);
          break;
        }
      }
      if (last == -1) continue;
      const Isometry3d g = truth[first].inverse() * truth[last];
      const Isometry3d r = estimate[first].inverse() * estimate[last];
      const Isometry3d e = r.inverse() * g;
      const double d = 0.5 * (e(0, 0) + e(1, 1) + e(2, 2) - 1.0);
      const double r_err = std::acos(std::max(std::min(d, 1.0), -1.0)) / len;
      const double t_err = e.translation().norm() / len;
      ASSERT_LT(s, summary.segments.size());
      EXPECT_EQ(summary.segments[s].first_frame, first);
      EXPECT_EQ(summary.segments[s].last_frame, static_cast<size_t>(last));
      EXPECT_NEAR(summary.segments[s].translation_error, t_err, 1e-12);
      EXPECT_NEAR(summary.segments[s].rotation_error, r_err, 1e-12);
      t_sum += t_err;
      r_sum += r_err;
      ++s;
    }
  }
  EXPECT_EQ(s, summary.segments.size());
  EXPECT_GT(s, 500u);
  EXPECT_NEAR(summary.translation_error_percent, 100.0 * t_sum / s, 1e-10);
  EXPECT_NEAR(
      summary.rotation_error_deg_per_m, r_sum / s * 180.0 / M_PI, 1e-10);
}

TEST(ComputeKittiSegmentErrors, Failures) {
  const std::vector<Isometry3d> truth = StraightLine(10.0);
  KittiSegmentSummary summary;
  std::string error;
  const std::vector<Isometry3d> shorter(truth.begin(), truth.end() - 1);
  EXPECT_FALSE(ComputeKittiSegmentErrors(
      KittiSegmentOptions(), truth, shorter, &summary, &error));
  EXPECT_NE(error.find("101 reference poses and 100"), std::string::npos)
      << error;
  KittiSegmentOptions options;
  options.first_frame_step = 0;
  EXPECT_FALSE(
      ComputeKittiSegmentErrors(options, truth, truth, &summary, &error));
  options = KittiSegmentOptions();
  options.lengths_m = {100, -5};
  EXPECT_FALSE(
      ComputeKittiSegmentErrors(options, truth, truth, &summary, &error));
  options.lengths_m = {100, 200, 100};
  EXPECT_FALSE(
      ComputeKittiSegmentErrors(options, truth, truth, &summary, &error));
  EXPECT_NE(error.find("twice"), std::string::npos) << error;
}

}  // namespace
}  // namespace mlndt
