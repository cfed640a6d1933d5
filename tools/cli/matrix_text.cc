#include "tools/cli/matrix_text.h"

#include <glog/logging.h>

#include <Eigen/Geometry>
#include <fstream>

#include "mlndt/common/rigid_transform.h"

namespace mlndt {
namespace tools {

namespace {

// The 4x4 matrix of the first 12 row-major numbers of `values` (12 or 16 of
// them); the last row is 0 0 0 1.
Eigen::Matrix4d RowMajorMatrix(const std::vector<double>& values) {
  CHECK(values.size() == 12 || values.size() == 16) << values.size();
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  for (int i = 0; i < 12; ++i) m(i / 4, i % 4) = values[static_cast<size_t>(i)];
  return m;
}

}  // namespace

bool RowMajorToRigidTransform(const std::vector<double>& values,
                              const std::string& what,
                              Isometry3d* transform,
                              std::string* error) {
  if (values.size() != 12) {
    *error = what + " needs 12 comma-separated numbers (row-major 3x4)";
    return false;
  }
  // Checked and re-orthonormalised as every pose read (rigid_transform.h).
  std::string problem;
  if (!ToRigidTransform(RowMajorMatrix(values), transform, &problem)) {
    *error = what + ": " + problem;
    return false;
  }
  return true;
}

bool ReadMatrixFile(const std::string& path,
                    Isometry3d* transform,
                    std::string* error) {
  std::ifstream in(path);
  if (!in) {
    *error = path + ": cannot open";
    return false;
  }
  std::vector<double> v;
  double x;
  while (in >> x) v.push_back(x);
  if (!in.eof() || (v.size() != 12 && v.size() != 16)) {
    *error =
        path + ": expected 12 or 16 numbers (a row-major 3x4 or 4x4 matrix)";
    return false;
  }
  Eigen::Matrix4d m = RowMajorMatrix(v);
  if (v.size() == 16) {
    for (int c = 0; c < 4; ++c) m(3, c) = v[static_cast<size_t>(12 + c)];
  }
  std::string problem;
  if (!ToRigidTransform(m, transform, &problem)) {
    *error = path + ": " + problem;
    return false;
  }
  return true;
}

}  // namespace tools
}  // namespace mlndt
