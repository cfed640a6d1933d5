#include "mlndt/cloud/cloud_filters.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace mlndt {
namespace {

TEST(RangeCrop, IsValid) {
  std::string error;
  EXPECT_TRUE(RangeCrop().IsValid(&error));
  EXPECT_TRUE((RangeCrop{2.0, 0.0}).IsValid(&error));
  EXPECT_TRUE((RangeCrop{2.0, 80.0}).IsValid(&error));
  EXPECT_FALSE((RangeCrop{-1.0, 0.0}).IsValid(&error));
  EXPECT_NE(error.find("min_range_m"), std::string::npos) << error;
  EXPECT_FALSE((RangeCrop{5.0, 5.0}).IsValid(&error));
  EXPECT_NE(error.find("max_range_m"), std::string::npos) << error;
  EXPECT_FALSE((RangeCrop{0.0, std::nan("")}).IsValid(&error));
  EXPECT_FALSE((RangeCrop{std::nan(""), 0.0}).IsValid(&error));
}

// Limits are inclusive, the order of the kept points is the input's, and
// non-finite points go whatever the limits.
TEST(CropByRange, KeepsPointsBetweenTheLimitsInOrder) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  PointCloud scan({{1, 0, 0},
                   {0, 3, 4},  // Range 5: on the upper limit.
                   {0.5, 0, 0},
                   {10, 0, 0},
                   {nan, 0, 0},
                   {0, -2, 0}});  // Range 2: on the lower limit.
  PointCloud copy = scan;
  EXPECT_EQ(CropByRange(RangeCrop{2.0, 5.0}, &scan), 4u);
  ASSERT_EQ(scan.size(), 2u);
  EXPECT_EQ(scan[0], Eigen::Vector3d(0, 3, 4));
  EXPECT_EQ(scan[1], Eigen::Vector3d(0, -2, 0));
  // No upper limit.
  EXPECT_EQ(CropByRange(RangeCrop{0.0, 0.0}, &copy), 1u);  // The NaN only.
  EXPECT_EQ(copy.size(), 5u);
  EXPECT_EQ(copy[3], Eigen::Vector3d(10, 0, 0));
}

TEST(CropByRangeDeathTest, InvalidCrop) {
  PointCloud scan({{1, 0, 0}});
  EXPECT_DEATH(CropByRange(RangeCrop{3.0, 1.0}, &scan), "max_range_m");
}

}  // namespace
}  // namespace mlndt
