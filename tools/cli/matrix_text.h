#pragma once

// Rigid transforms written as row-major matrices: 12 numbers (3x4) or 16
// (4x4), from a flag or a text file. The one place the tools turn such
// numbers into a transform.

#include <string>
#include <vector>

#include "mlndt/common/types.h"

namespace mlndt {
namespace tools {

// The transform of exactly 12 row-major numbers that passes
// ToRigidTransform (mlndt/common/rigid_transform.h: a rotation within 1e-3,
// re-orthonormalised; a translation within 1e8 m); false with *error naming
// `what` (e.g. "--initial_matrix") otherwise.
bool RowMajorToRigidTransform(const std::vector<double>& values,
                              const std::string& what,
                              Isometry3d* transform,
                              std::string* error);

// Reads 12 or 16 whitespace-separated numbers (row-major 3x4 or 4x4) that
// pass ToRigidTransform (a reflection, a scaled matrix or a 1e300
// translation is refused; the rotation is re-orthonormalised).
bool ReadMatrixFile(const std::string& path,
                    Isometry3d* transform,
                    std::string* error);

}  // namespace tools
}  // namespace mlndt
