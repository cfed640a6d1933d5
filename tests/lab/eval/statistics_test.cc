#include "lab/eval/statistics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace mlndt {
namespace {

TEST(ComputeStats, EvenCountAveragesTheTwoMiddleValues) {
  const Stats s = ComputeStats({4.0, 1.0, 3.0, 2.0});
  EXPECT_EQ(s.count, 4u);
  EXPECT_DOUBLE_EQ(s.mean, 2.5);
  EXPECT_DOUBLE_EQ(s.median, 2.5);
  EXPECT_DOUBLE_EQ(s.min, 1.0);
  EXPECT_DOUBLE_EQ(s.max, 4.0);
  // Sample standard deviation: sum of squares 5, divided by n - 1 = 3.
  EXPECT_DOUBLE_EQ(s.std, std::sqrt(5.0 / 3.0));
  // Nearest rank: ceil(0.95 * 4) = 4 -> the largest value.
  EXPECT_DOUBLE_EQ(s.p95, 4.0);
}

TEST(ComputeStats, OddCountTakesTheMiddleValue) {
  const Stats s = ComputeStats({10.0, -1.0, 7.0});
  EXPECT_DOUBLE_EQ(s.median, 7.0);
  EXPECT_DOUBLE_EQ(s.mean, 16.0 / 3.0);
}

TEST(ComputeStats, P95IsTheNearestRank) {
  std::vector<double> values;
  for (int i = 20; i >= 1; --i) values.push_back(i);  // Unsorted on purpose.
  // ceil(0.95 * 20) = 19: the 19th smallest value.
  EXPECT_DOUBLE_EQ(ComputeStats(values).p95, 19.0);
  values.push_back(21.0);
  // ceil(0.95 * 21) = ceil(19.95) = 20.
  EXPECT_DOUBLE_EQ(ComputeStats(values).p95, 20.0);
}

TEST(ComputeStats, OneValueHasZeroStdAndEmptyIsAllZero) {
  const Stats one = ComputeStats({3.5});
  EXPECT_DOUBLE_EQ(one.std, 0.0);
  EXPECT_DOUBLE_EQ(one.median, 3.5);
  EXPECT_DOUBLE_EQ(one.p95, 3.5);
  const Stats none = ComputeStats({});
  EXPECT_EQ(none.count, 0u);
  EXPECT_EQ(none.mean, 0.0);
  EXPECT_EQ(none.max, 0.0);
}

TEST(Rms, RootOfTheMeanSquare) {
  EXPECT_DOUBLE_EQ(Rms({3.0, -4.0}), std::sqrt(12.5));
  EXPECT_DOUBLE_EQ(Rms({2.0, 2.0, 2.0}), 2.0);
  EXPECT_EQ(Rms({}), 0.0);
}

}  // namespace
}  // namespace mlndt
