#pragma once

// Rigid transforms written as row-major matrices: 12 numbers (3x4) or 16
// (4x4), from a flag or a text file. The one place the tools turn such
// numbers into a transform.

#include <string>
#include <vector>

#include "mlndt/common/types.h"

namespace mlndt {
namespace tools {

// The 4x4 matrix of the first 12 row-major numbers of `values` (12 or 16 of
// them); the last row is 0 0 0 1.
Eigen::Matrix4d RowMajorMatrix(const std::vector<double>& values);

// The transform of exactly 12 row-major numbers whose 3x3 part is a
// rotation within 1e-3, re-orthonormalised; false with *error naming `what`
// (e.g. "--initial_matrix") otherwise.
bool RowMajorToRigidTransform(const std::vector<double>& values,
                              const std::string& what,
                              Isometry3d* transform,
                              std::string* error);

// Reads 12 or 16 whitespace-separated numbers (row-major 3x4 or 4x4), kept
// as written (not re-orthonormalised).
bool ReadMatrixFile(const std::string& path,
                    Isometry3d* transform,
                    std::string* error);

}  // namespace tools
}  // namespace mlndt
