#pragma once

// ScalarPart(): the value of a double or of a ceres::Jet, without its
// derivative part. Cell lookups inside auto-diff cost functors use it: the
// cell is chosen from the scalar value of the transformed point, and the
// derivatives flow only through the point itself (the pattern of the JetT
// overloads in ceres/cubic_interpolation.h).

#include <ceres/jet.h>

namespace mlndt {

inline double ScalarPart(double value) { return value; }

template <typename T, int N>
double ScalarPart(const ceres::Jet<T, N>& value) {
  return ScalarPart(value.a);
}

}  // namespace mlndt
