#pragma once

// Least-squares alignment of two point sets: the rigid or similarity
// transform that maps `source` points onto `target` points (S. Umeyama,
// "Least-squares estimation of transformation parameters between two point
// patterns", IEEE TPAMI 13(4):376-380, 1991).

#include <string>
#include <vector>

#include "mlndt/common/types.h"

namespace mlndt {

// y = scale * rotation * x + translation; scale is 1 for a rigid transform.
struct SimilarityTransform {
  Matrix3d rotation = Matrix3d::Identity();
  Vector3d translation = Vector3d::Zero();
  double scale = 1.0;

  Vector3d operator*(const Vector3d& x) const {
    return scale * (rotation * x) + translation;
  }
};

// Minimises sum_i |target_i - (c R source_i + t)|^2 over rotations R,
// translations t and, when with_scale, scales c > 0 (else c = 1), as in
// Umeyama's Eqs. (34)-(43). Points are paired by index. False with *error
// when the sizes differ, there are fewer than 3 pairs, or the source points
// all coincide. When the points are collinear the rotation about their line
// is not determined, and one of the equally good rotations is returned.
bool UmeyamaAlignment(const std::vector<Vector3d>& source,
                      const std::vector<Vector3d>& target,
                      bool with_scale,
                      SimilarityTransform* target_from_source,
                      std::string* error);

}  // namespace mlndt
