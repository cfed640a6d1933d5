#include "mlndt/cloud/range_filter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "mlndt/cloud/io.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

// 1000 points on a 10 m sphere shell, with `near` points at 0.1 m and
// `saturated` points at 30 m (a scanner's "no return" value).
PointCloud Scan(int near, int saturated) {
  std::mt19937 rng(3);
  std::normal_distribution<double> n(0.0, 1.0);
  PointCloud cloud;
  const auto direction = [&] {
    return Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized();
  };
  for (int i = 0; i < 1000; ++i) cloud.Add((10.0 + 0.5 * n(rng)) * direction());
  for (int i = 0; i < near; ++i) cloud.Add(0.1 * direction());
  for (int i = 0; i < saturated; ++i) cloud.Add(30.0 * direction());
  return cloud;
}

TEST(FilterByRange, DropsPointsAtTheSensorAndAtASaturatedMaximum) {
  RangeFilterSummary summary;
  const PointCloud kept =
      FilterByRange(RangeFilterOptions(), Scan(40, 20), &summary);
  EXPECT_EQ(summary.input_points, 1060u);
  EXPECT_EQ(summary.too_close, 40u);
  EXPECT_EQ(summary.saturated, 20u);
  EXPECT_EQ(summary.too_far, 0u);
  EXPECT_EQ(summary.kept_points, 1000u);
  ASSERT_EQ(kept.size(), 1000u);
  for (const Eigen::Vector3d& p : kept.points()) {
    EXPECT_GT(p.norm(), 5.0);
    EXPECT_LT(p.norm(), 20.0);
  }
}

TEST(FilterByRange, AFewPointsAtTheLargestRangeAreKept) {
  // 2 of 1002 at the maximum: a real far return, not a saturated range.
  RangeFilterSummary summary;
  FilterByRange(RangeFilterOptions(), Scan(0, 2), &summary);
  EXPECT_EQ(summary.saturated, 0u);
  EXPECT_EQ(summary.kept_points, 1002u);
  RangeFilterOptions off;
  off.saturated_range_fraction = 0.0;
  FilterByRange(off, Scan(0, 20), &summary);
  EXPECT_EQ(summary.kept_points, 1020u);
}

TEST(FilterByRange, MaxRangeAndOrderKept) {
  PointCloud cloud;
  for (double r : {0.5, 12.0, 3.0, 50.0, 7.0})
    cloud.Add(Eigen::Vector3d(r, 0, 0));
  RangeFilterOptions options;
  options.max_range_m = 10.0;
  options.saturated_range_fraction = 0.0;
  RangeFilterSummary summary;
  const PointCloud kept = FilterByRange(options, cloud, &summary);
  ASSERT_EQ(kept.size(), 3u);
  EXPECT_EQ(kept[0].x(), 0.5);
  EXPECT_EQ(kept[1].x(), 3.0);
  EXPECT_EQ(kept[2].x(), 7.0);
  EXPECT_EQ(summary.too_far, 2u);
}

TEST(RangeFilterOptions, RangesAreChecked) {
  std::string error;
  EXPECT_TRUE(RangeFilterOptions().IsValid(&error)) << error;
  RangeFilterOptions options;
  options.min_range_m = -1.0;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_NE(error.find("min_range_m"), std::string::npos) << error;
  options = RangeFilterOptions();
  options.max_range_m = 0.1;  // Below min_range_m.
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_NE(error.find("max_range_m"), std::string::npos) << error;
  options = RangeFilterOptions();
  options.saturated_range_fraction = std::nan("");
  EXPECT_FALSE(options.IsValid(&error));
}

TEST(FilterByRange, Koide3ScanLosesItsReturnsAtTheOrigin) {
  PointCloud cloud;
  std::string error;
  ASSERT_TRUE(ReadPointCloud(testing::BundledDataPath("koide3/251370668.pcd"),
                             &cloud,
                             nullptr,
                             &error))
      << error;
  RangeFilterSummary summary;
  FilterByRange(RangeFilterOptions(), cloud, &summary);
  // 5032 of the 69088 returns sit at (0, 0, 0); none is farther than 0.25 m
  // and closer than 1 m.
  EXPECT_EQ(summary.too_close, 5032u);
  EXPECT_EQ(summary.saturated, 0u);
}

TEST(FilterByRange, ThreeDtkScanLosesItsInvalidReturns) {
  MLNDT_REQUIRE_SHARED_DATA(dir);
  PointCloud cloud;
  std::string error;
  ASSERT_TRUE(ReadPointCloud(
      dir + "/3dtk_example_scans/scan000.3d", &cloud, nullptr, &error))
      << error;
  RangeFilterSummary summary;
  FilterByRange(RangeFilterOptions(), cloud, &summary);
  // The data set's README: a cluster at about 0.1 m and 1481 points at the
  // 32.77 m maximum.
  EXPECT_GE(summary.too_close, 1892u);
  EXPECT_LT(summary.too_close, 2000u);
  EXPECT_EQ(summary.saturated, 1481u);
}

}  // namespace
}  // namespace mlndt
