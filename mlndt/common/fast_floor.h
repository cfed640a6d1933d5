#pragma once

// floor() for values already known to be in the int64 range. Without
// SSE4.1 (the x86-64 baseline Debian builds for) std::floor is a libm call;
// this is two instructions, and cell lookups do it for every point.

#include <cstdint>

namespace mlndt {

// Requires |x| < 2^62 (callers range-check first; NaN must not get here).
inline int64_t FloorToInt64(double x) {
  const int64_t truncated = static_cast<int64_t>(x);
  return static_cast<double>(truncated) > x ? truncated - 1 : truncated;
}

}  // namespace mlndt
