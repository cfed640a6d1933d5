#pragma once

// Range thresholds on squared ranges. A range filter that tests
// sqrt(s) < m for every point's squared range s can test s < T instead,
// with T the smallest s for which sqrt(s) >= m: sqrt is correctly rounded
// and monotone, so both tests decide alike for every double s >= 0, and the
// per-point sqrt goes away. m * m alone is not T: it is rounded, and the
// rounding of sqrt can move the boundary by an ulp either way.

#include <cmath>
#include <limits>

namespace mlndt {
namespace internal {

// The smallest double s >= 0 with holds(sqrt(s)), for a predicate of the
// form r >= m or r > m (monotone in r), starting from the guess m * m.
template <typename Holds>
double SmallestSquareWhere(double m, Holds holds) {
  if (holds(0.0)) return 0.0;
  double t = m * m;
  if (!(t >= 0.0)) t = 0.0;  // NaN guard; holds(0) is false here.
  const double inf = std::numeric_limits<double>::infinity();
  while (t > 0.0 && holds(std::sqrt(std::nextafter(t, 0.0)))) {
    t = std::nextafter(t, 0.0);
  }
  while (t < inf && !holds(std::sqrt(t))) t = std::nextafter(t, inf);
  return t;
}

}  // namespace internal

// The smallest s >= 0 with sqrt(s) >= m: sqrt(s) < m <=> s < it. Infinity
// when m is infinite (only an infinite s reaches it).
inline double SmallestSquareWithRangeAtLeast(double m) {
  return internal::SmallestSquareWhere(m, [m](double r) { return r >= m; });
}

// The smallest s >= 0 with sqrt(s) > m: sqrt(s) > m <=> s >= it.
inline double SmallestSquareWithRangeAbove(double m) {
  return internal::SmallestSquareWhere(m, [m](double r) { return r > m; });
}

}  // namespace mlndt
