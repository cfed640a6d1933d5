#include "mlndt/cloud/range_filter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "mlndt/cloud/internal/squared_range.h"
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

// Into a buffer: the same points and counts as by value, the previous
// points replaced, and a buffer that holds the kept points keeps its memory.
TEST(FilterByRange, IntoABufferReusesItsMemory) {
  const PointCloud scan = Scan(40, 20);
  RangeFilterSummary by_value_summary, summary;
  const PointCloud by_value =
      FilterByRange(RangeFilterOptions(), scan, &by_value_summary);
  PointCloud buffer;
  buffer.Reserve(scan.size());
  for (int i = 0; i < 5; ++i) buffer.Add(Eigen::Vector3d(7.0, 7.0, 7.0));
  const Eigen::Vector3d* memory = buffer.points().data();
  FilterByRange(RangeFilterOptions(), scan, &buffer, &summary);
  EXPECT_EQ(buffer.points(), by_value.points());
  EXPECT_EQ(summary.kept_points, by_value_summary.kept_points);
  EXPECT_EQ(summary.too_close, by_value_summary.too_close);
  EXPECT_EQ(summary.saturated, by_value_summary.saturated);
  EXPECT_EQ(buffer.points().data(), memory);
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

// The filter as first written: a sqrt per point, thresholds on ranges.
PointCloud FilterByRangeWithSqrt(const RangeFilterOptions& options,
                                 const PointCloud& cloud,
                                 RangeFilterSummary* counts) {
  *counts = RangeFilterSummary();
  counts->input_points = cloud.size();
  std::vector<double> ranges(cloud.size());
  double largest = 0.0;
  for (size_t i = 0; i < cloud.size(); ++i) {
    ranges[i] = cloud[i].norm();
    largest = std::max(largest, ranges[i]);
  }
  const double at_largest = static_cast<double>(
      std::count_if(ranges.begin(), ranges.end(), [&](double r) {
        return r >= largest - 0.01;
      }));
  const bool saturated = options.saturated_range_fraction > 0.0 &&
                         at_largest >= options.saturated_range_fraction *
                                           static_cast<double>(cloud.size());
  PointCloud kept;
  for (size_t i = 0; i < cloud.size(); ++i) {
    const double r = ranges[i];
    if (r < options.min_range_m) {
      ++counts->too_close;
    } else if (options.max_range_m > 0.0 && r > options.max_range_m) {
      ++counts->too_far;
    } else if (saturated && r >= largest - 0.01) {
      ++counts->saturated;
    } else {
      kept.Add(cloud[i]);
    }
  }
  counts->kept_points = kept.size();
  return kept;
}

void ExpectSameAsSqrtFilter(const RangeFilterOptions& options,
                            const PointCloud& cloud) {
  RangeFilterSummary expected_counts, counts;
  const PointCloud expected =
      FilterByRangeWithSqrt(options, cloud, &expected_counts);
  const PointCloud kept = FilterByRange(options, cloud, &counts);
  EXPECT_EQ(kept.points(), expected.points());
  EXPECT_EQ(counts.too_close, expected_counts.too_close);
  EXPECT_EQ(counts.too_far, expected_counts.too_far);
  EXPECT_EQ(counts.saturated, expected_counts.saturated);
  EXPECT_EQ(counts.kept_points, expected_counts.kept_points);
}

TEST(FilterByRange, SameAsTheSqrtFilterOnRealScans) {
  for (const char* scan : {"kitti/pcd/000000.pcd",
                           "koide3/251370668.pcd",
                           "koide3/251371071.pcd"}) {
    SCOPED_TRACE(scan);
    PointCloud cloud;
    std::string error;
    ASSERT_TRUE(
        ReadPointCloud(testing::BundledDataPath(scan), &cloud, nullptr, &error))
        << error;
    RangeFilterOptions options;
    ExpectSameAsSqrtFilter(options, cloud);
    // Thresholds through the scan's ranges, and a saturation band that
    // holds many points (fraction 1e-6: any point at the largest range).
    options.min_range_m = 3.0;
    options.max_range_m = 20.0;
    options.saturated_range_fraction = 1e-6;
    ExpectSameAsSqrtFilter(options, cloud);
  }
}

TEST(FilterByRange, SameAsTheSqrtFilterAtTheThresholds) {
  // Points whose range is the threshold itself and its neighbouring
  // doubles, along directions whose squared norm rounds differently.
  RangeFilterOptions options;
  options.min_range_m = 0.3;
  options.max_range_m = 7.1;
  options.saturated_range_fraction = 0.0;
  PointCloud cloud;
  for (double r : {options.min_range_m, options.max_range_m}) {
    for (int ulps = -4; ulps <= 4; ++ulps) {
      double value = r;
      for (int u = 0; u < std::abs(ulps); ++u) {
        value = std::nextafter(value, ulps < 0 ? 0.0 : 1e9);
      }
      for (const Eigen::Vector3d& d :
           {Eigen::Vector3d(1, 0, 0),
            Eigen::Vector3d(0.6, 0.8, 0),
            Eigen::Vector3d(Eigen::Vector3d(1, 1, 1).normalized()),
            Eigen::Vector3d(Eigen::Vector3d(2, -3, 6) / 7.0)}) {
        cloud.Add(value * d);
      }
    }
  }
  ExpectSameAsSqrtFilter(options, cloud);
}

TEST(SquaredRange, ThresholdsDecideAsTheSqrtDoes) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> log_range(-3.0, 6.0);
  for (int i = 0; i < 2000; ++i) {
    const double m = std::pow(10.0, log_range(rng));
    const double at_least = SmallestSquareWithRangeAtLeast(m);
    const double above = SmallestSquareWithRangeAbove(m);
    for (double s : {at_least, above}) {
      for (double t : {std::nextafter(s, 0.0), s, std::nextafter(s, 1e300)}) {
        EXPECT_EQ(std::sqrt(t) >= m, t >= at_least) << m << " " << t;
        EXPECT_EQ(std::sqrt(t) > m, t >= above) << m << " " << t;
      }
    }
  }
  EXPECT_EQ(SmallestSquareWithRangeAtLeast(0.0), 0.0);
  EXPECT_EQ(SmallestSquareWithRangeAtLeast(-1.0), 0.0);
  EXPECT_EQ(SmallestSquareWithRangeAtLeast(INFINITY), INFINITY);
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
