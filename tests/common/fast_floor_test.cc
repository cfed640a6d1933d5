// FloorToInt64 agrees with std::floor, negatives and integers included.

#include "mlndt/common/fast_floor.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mlndt {
namespace {

TEST(FloorToInt64, MatchesStdFloor) {
  for (const double x : {0.0,
                         -0.0,
                         0.5,
                         -0.5,
                         1.0,
                         -1.0,
                         2.999999,
                         -2.999999,
                         -3.0,
                         1e-300,
                         -1e-300,
                         4e6 + 0.25,
                         -4e6 - 0.25,
                         1e15 + 0.5,
                         -(1e15 + 0.5)}) {
    EXPECT_EQ(FloorToInt64(x), static_cast<int64_t>(std::floor(x))) << x;
  }
}

}  // namespace
}  // namespace mlndt
