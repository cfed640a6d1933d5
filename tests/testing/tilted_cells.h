#pragma once

// Small hand-made cells for the score and residual tests: covariances
// turned off the axes (non-diagonal whitening), and a three-cell layer.

#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "mlndt/common/types.h"
#include "mlndt/grid/ndt_cell.h"
#include "mlndt/grid/ndt_layer.h"

namespace mlndt {
namespace testing {

using Eigen::Matrix3d;
using Eigen::Vector3d;

// A covariance with `eigenvalues` along axes turned by `angle` about `axis`.
inline Matrix3d TiltedCovariance(const Vector3d& eigenvalues,
                                 double angle,
                                 const Vector3d& axis) {
  const Matrix3d q =
      Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
  return q * eigenvalues.asDiagonal() * q.transpose();
}

// Origin 0, 2 m cells, 4 x 3 x 2 grid; occupied cells (1, 1, 0), (3, 1, 1)
// and (2, 2, 0) with non-diagonal covariances. Cell (2, 1, 0) is empty.
inline NdtLayer ThreeCellLayer() {
  const auto key = [](int i, int j, int k) -> int64_t {
    return i + 4 * (j + 3 * k);
  };
  std::vector<NdtCell> cells(3);
  EXPECT_TRUE(
      MakeNdtCell(20,
                  Vector3d(3.1, 2.9, 0.8),
                  TiltedCovariance({0.40, 0.15, 0.05}, 0.7, {1.0, 2.0, -0.5}),
                  CellRegularization(),
                  &cells[0]));
  EXPECT_TRUE(
      MakeNdtCell(20,
                  Vector3d(7.0, 3.2, 2.9),
                  TiltedCovariance({0.30, 0.20, 0.02}, 1.1, {-0.3, 1.0, 1.0}),
                  CellRegularization(),
                  &cells[1]));
  EXPECT_TRUE(
      MakeNdtCell(20,
                  Vector3d(5.2, 4.6, 1.1),
                  TiltedCovariance({0.50, 0.10, 0.03}, 0.4, {0.2, -1.0, 0.6}),
                  CellRegularization(),
                  &cells[2]));
  return NdtLayer(Vector3d::Zero(),
                  2.0,
                  Eigen::Vector3i(4, 3, 2),
                  cells,
                  {key(1, 1, 0), key(3, 1, 1), key(2, 2, 0)});
}

}  // namespace testing
}  // namespace mlndt
