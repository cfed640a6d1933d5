#include "mlndt/grid/cell_coverage.h"

#include <gtest/gtest.h>

namespace mlndt {
namespace {

TEST(CoveredPointFraction, CountsThePointsOfCellsWithEnoughPoints) {
  // 10 + 5 of 20 points lie in cells of >= 5 points.
  EXPECT_DOUBLE_EQ(CoveredPointFraction({10, 2, 3, 5}, 5), 0.75);
  EXPECT_DOUBLE_EQ(CoveredPointFraction({10, 2, 3, 5}, 11), 0.0);
  EXPECT_DOUBLE_EQ(CoveredPointFraction({10, 2, 3, 5}, 2), 1.0);
}

TEST(CoveredPointFraction, NoPointsCoverNothing) {
  EXPECT_DOUBLE_EQ(CoveredPointFraction({}, 5), 0.0);
  EXPECT_DOUBLE_EQ(CoveredPointFraction({0, 0}, 5), 0.0);
}

}  // namespace
}  // namespace mlndt
