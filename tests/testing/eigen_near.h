#pragma once

// EigenNear(actual, expected, tolerance): element-wise comparison of two Eigen
// matrices for EXPECT_TRUE; non-finite entries in `actual` fail (tests pre-fill
// outputs with NaN so that unwritten entries show up).

#include <gtest/gtest.h>

#include <Eigen/Core>

namespace mlndt {
namespace testing {

template <typename A, typename B>
::testing::AssertionResult EigenNear(const Eigen::MatrixBase<A>& actual,
                                     const Eigen::MatrixBase<B>& expected,
                                     double tolerance) {
  if (actual.rows() != expected.rows() || actual.cols() != expected.cols()) {
    return ::testing::AssertionFailure() << "size mismatch";
  }
  if (!actual.allFinite()) {
    return ::testing::AssertionFailure() << "non-finite entries:\n" << actual;
  }
  const double difference = (actual - expected).cwiseAbs().maxCoeff();
  if (difference > tolerance) {
    return ::testing::AssertionFailure() << "max |difference| " << difference
                                         << " > " << tolerance << "\nactual:\n"
                                         << actual << "\nexpected:\n"
                                         << expected;
  }
  return ::testing::AssertionSuccess();
}

}  // namespace testing
}  // namespace mlndt
