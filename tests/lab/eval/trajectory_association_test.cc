#include "lab/eval/trajectory_association.h"

#include <gtest/gtest.h>

#include <vector>

namespace mlndt {
namespace {

// A trajectory whose pose k sits at x = marker_k, so that tests can see
// which pose was copied.
Trajectory AtTimes(const std::vector<double>& times, double marker_offset) {
  Trajectory trajectory;
  for (size_t k = 0; k < times.size(); ++k) {
    Isometry3d pose = Isometry3d::Identity();
    pose.translation().x() = marker_offset + static_cast<double>(k);
    trajectory.Add(times[k], pose);
  }
  return trajectory;
}

TEST(AssociateByIndex, PairsEqualIndicesUpToTheShorter) {
  const Trajectory reference = AtTimes({0, 1, 2, 3, 4}, 0.0);
  const Trajectory estimate = AtTimes({10, 11, 12}, 100.0);
  const AssociatedPoses pairs = AssociateByIndex(reference, estimate);
  ASSERT_EQ(pairs.size(), 3u);
  EXPECT_EQ(pairs.reference_indices, (std::vector<size_t>{0, 1, 2}));
  EXPECT_EQ(pairs.estimate_indices, (std::vector<size_t>{0, 1, 2}));
  EXPECT_EQ(pairs.reference[2].translation().x(), 2.0);
  EXPECT_EQ(pairs.estimate[2].translation().x(), 102.0);
}

TEST(AssociateByTimestamp, NearestWithinTheLimitEachPoseOnce) {
  const Trajectory reference = AtTimes({0.0, 0.1, 0.2, 0.3, 0.4, 0.5}, 0.0);
  // 0.01 -> ref 0; 0.09 -> ref 1; 0.115 -> also ref 1 but farther (dropped);
  // 0.25 -> 0.05 from refs 2 and 3 (beyond 0.02: dropped); 0.301 -> ref 3;
  // 0.49 -> ref 5 (0.01) ; 0.7 -> nothing near.
  const Trajectory estimate =
      AtTimes({0.01, 0.09, 0.115, 0.25, 0.301, 0.49, 0.7}, 100.0);
  const AssociatedPoses pairs = AssociateByTimestamp(reference, estimate, 0.02);
  EXPECT_EQ(pairs.reference_indices, (std::vector<size_t>{0, 1, 3, 5}));
  EXPECT_EQ(pairs.estimate_indices, (std::vector<size_t>{0, 1, 4, 5}));
  ASSERT_EQ(pairs.size(), 4u);
  EXPECT_EQ(pairs.reference[2].translation().x(), 3.0);
  EXPECT_EQ(pairs.estimate[2].translation().x(), 104.0);
}

TEST(AssociateByTimestamp, LaterCloserEstimateReplacesAnEarlierOne) {
  const Trajectory reference = AtTimes({1.0, 2.0}, 0.0);
  const Trajectory estimate = AtTimes({0.95, 0.99, 1.04}, 100.0);
  const AssociatedPoses pairs = AssociateByTimestamp(reference, estimate, 0.1);
  EXPECT_EQ(pairs.reference_indices, (std::vector<size_t>{0}));
  EXPECT_EQ(pairs.estimate_indices, (std::vector<size_t>{1}));
}

TEST(AssociateByTimestamp, ExactLimitIsIncludedAndEmptyInputsGiveNoPairs) {
  const Trajectory reference = AtTimes({0.0, 1.0}, 0.0);
  const Trajectory estimate = AtTimes({0.25, 1.5}, 0.0);
  EXPECT_EQ(AssociateByTimestamp(reference, estimate, 0.25).size(), 1u);
  EXPECT_EQ(AssociateByTimestamp(reference, estimate, 0.5).size(), 2u);
  EXPECT_EQ(AssociateByTimestamp(Trajectory(), estimate, 1.0).size(), 0u);
  EXPECT_EQ(AssociateByTimestamp(reference, Trajectory(), 1.0).size(), 0u);
}

}  // namespace
}  // namespace mlndt
