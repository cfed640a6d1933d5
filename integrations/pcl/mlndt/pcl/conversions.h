#pragma once

// PCL's clouds and matrices into mlndt's types.
//
// Clouds into mlndt's PointCloud, the way mlndt's readers fill one
// (mlndt/cloud/io.h): each point's x, y, z cast from float to double, in the
// cloud's order, and a point with a NaN or infinite coordinate dropped and
// counted. A cloud loaded with pcl::io::loadPCDFile and converted here holds
// the same doubles, in the same order, as mlndt::ReadPointCloud gives for
// the same file, so mlndt::Register sees the same points either way.

#include <pcl/point_cloud.h>

#include <Eigen/Core>
#include <cmath>
#include <cstddef>
#include <string>

#include "mlndt/cloud/point_cloud.h"
#include "mlndt/common/types.h"

namespace mlndt {
namespace pcl {

// The finite points of `cloud`. `dropped` (may be null) receives how many
// points were dropped as non-finite. PointT is any PCL point type with float
// x, y, z.
template <typename PointT>
PointCloud ToPointCloud(const ::pcl::PointCloud<PointT>& cloud,
                        size_t* dropped = nullptr) {
  PointCloud points;
  points.Reserve(cloud.size());
  size_t removed = 0;
  for (const PointT& point : cloud) {
    const Eigen::Vector3d p(static_cast<double>(point.x),
                            static_cast<double>(point.y),
                            static_cast<double>(point.z));
    if (p.allFinite()) {
      points.Add(p);
    } else {
      ++removed;
    }
  }
  if (dropped != nullptr) *dropped = removed;
  return points;
}

// A PCL transformation (float 4x4, as align()'s guess) as an Isometry3d:
// each entry cast to double, the last row set to exactly (0, 0, 0, 1).
// False with *error when an entry is not finite, the last row is not
// (0, 0, 0, 1) within 1e-6, or the rotation block R is not a rotation
// (|R^T R - I| > 1e-4 in an entry, or det R < 0).
inline bool ToIsometry(const Eigen::Matrix4f& matrix,
                       Isometry3d* transform,
                       std::string* error) {
  const Eigen::Matrix4d m = matrix.cast<double>();
  if (!m.allFinite()) {
    *error = "the transformation has a NaN or infinite entry";
    return false;
  }
  if ((m.row(3) - Eigen::RowVector4d(0.0, 0.0, 0.0, 1.0))
          .cwiseAbs()
          .maxCoeff() > 1e-6) {
    *error = "the transformation's last row is not (0, 0, 0, 1)";
    return false;
  }
  const Eigen::Matrix3d r = m.topLeftCorner<3, 3>();
  if ((r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() >
          1e-4 ||
      r.determinant() < 0.0) {
    *error =
        "the transformation's rotation block is not a rotation "
        "(R^T R != I within 1e-4, or det R < 0)";
    return false;
  }
  transform->matrix() = m;
  transform->matrix().row(3) << 0.0, 0.0, 0.0, 1.0;
  return true;
}

}  // namespace pcl
}  // namespace mlndt
