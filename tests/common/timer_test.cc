// NowSeconds: a monotonic clock in seconds.

#include "mlndt/common/timer.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace mlndt {
namespace {

TEST(NowSeconds, IsMonotonicAndInSeconds) {
  const double start = NowSeconds();
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  const double elapsed = NowSeconds() - start;
  EXPECT_GE(elapsed, 0.019);
  EXPECT_LT(elapsed, 5.0);  // Seconds, not milliseconds.
  double previous = NowSeconds();
  for (int k = 0; k < 1000; ++k) {
    const double now = NowSeconds();
    EXPECT_GE(now, previous);
    previous = now;
  }
}

}  // namespace
}  // namespace mlndt
