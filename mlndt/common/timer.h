#pragma once

// Wall-clock time in seconds from a monotonic clock, for timings and traces.

#include <chrono>

namespace mlndt {

inline double NowSeconds() {
  return std::chrono::duration<double>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

}  // namespace mlndt
