#pragma once

// ScalarPart(): the value of a double or of a ceres::Jet, without its
// derivative part. Cell lookups inside auto-diff cost functors use it: the
// cell is chosen from the scalar value of the transformed point, and the
// derivatives flow only through the point itself (the pattern of the JetT
// overloads in ceres/cubic_interpolation.h).

#include <ceres/jet.h>

#include <Eigen/Core>
#include <cstring>
#include <type_traits>

#include "mlndt/common/pose.h"

namespace mlndt {

inline double ScalarPart(double value) { return value; }

template <typename T, int N>
double ScalarPart(const ceres::Jet<T, N>& value) {
  return ScalarPart(value.a);
}

// True when a and b hold the same bits (a Jet's derivative part included;
// Jet's operator== compares the scalar part only, and memcmp of a whole Jet
// would read its alignment padding).
inline bool SameBits(double a, double b) {
  return std::memcmp(&a, &b, sizeof(a)) == 0;
}

template <typename T, int N>
bool SameBits(const ceres::Jet<T, N>& a, const ceres::Jet<T, N>& b) {
  if (!SameBits(a.a, b.a)) return false;
  for (int i = 0; i < N; ++i) {
    if (!SameBits(a.v[i], b.v[i])) return false;
  }
  return true;
}

// EulerRotation (Eq. 7) of angles[0..2], memoised per thread. Ceres
// evaluates every point's residual block at the same pose, so with one block
// per point the rotation (three sin/cos of Jets and their products) would be
// recomputed for every point. A hit needs identical bits, so it returns
// exactly what EulerRotation would.
template <typename T>
const Eigen::Matrix<T, 3, 3>& CachedEulerRotation(const T* angles) {
  thread_local T cached[3];
  thread_local bool valid = false;
  thread_local Eigen::Matrix<T, 3, 3> rotation;
  if (!valid || !SameBits(cached[0], angles[0]) ||
      !SameBits(cached[1], angles[1]) || !SameBits(cached[2], angles[2])) {
    for (int i = 0; i < 3; ++i) cached[i] = angles[i];
    rotation = EulerRotation(angles[0], angles[1], angles[2]);
    valid = true;
  }
  return rotation;
}

// x' = R(xi) x + t(xi) (Eq. 6) with the memoised rotation.
template <typename T>
Eigen::Matrix<T, 3, 1> CachedTransformPoint(const T* xi,
                                            const Eigen::Vector3d& x) {
  return CachedEulerRotation(xi + 3) * x.cast<T>() +
         Eigen::Matrix<T, 3, 1>(xi[0], xi[1], xi[2]);
}

// m v for a 3x3 m and a constant v, one of them of Jets: the values of
// Eigen's m * v with the constant cast to Jets, without multiplying by the
// cast's zero derivative part (a Jet times a double: 6 products a Jet
// instead of 13 and 6 sums). Eigen's fixed-size product sums each row as
// p0 + (p1 + p2) (redux_novec_unroller), and so does this, so the scalar
// parts have the same bits and the derivatives the same values (a zero's
// sign aside: Jet's product adds f.a * 0 to f.v * g.a).
template <typename M, typename V>
auto JetTimesConstant(const M& m, const V& v) {
  using J = std::decay_t<decltype(m(0, 0) * v(0))>;
  Eigen::Matrix<J, 3, 1> out;
  for (int i = 0; i < 3; ++i) {
    out(i) = m(i, 0) * v(0) + (m(i, 1) * v(1) + m(i, 2) * v(2));
  }
  return out;
}

// CachedTransformPoint for Jets: x is constant, so R x is JetTimesConstant
// (the same values as the generic version, and the same bits of the scalar
// part).
template <int N>
Eigen::Matrix<ceres::Jet<double, N>, 3, 1> CachedTransformPoint(
    const ceres::Jet<double, N>* xi, const Eigen::Vector3d& x) {
  Eigen::Matrix<ceres::Jet<double, N>, 3, 1> out =
      JetTimesConstant(CachedEulerRotation(xi + 3), x);
  for (int i = 0; i < 3; ++i) out(i) += xi[i];
  return out;
}

}  // namespace mlndt
