#pragma once

// A point cloud: finite 3D points in metres, in one frame.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstddef>
#include <vector>

namespace mlndt {

class PointCloud {
 public:
  PointCloud() = default;
  explicit PointCloud(std::vector<Eigen::Vector3d> points)
      : points_(std::move(points)) {}

  size_t size() const { return points_.size(); }
  bool empty() const { return points_.empty(); }
  const Eigen::Vector3d& operator[](size_t i) const { return points_[i]; }
  const std::vector<Eigen::Vector3d>& points() const { return points_; }
  std::vector<Eigen::Vector3d>* mutable_points() { return &points_; }

  void Reserve(size_t n) { points_.reserve(n); }
  void Add(const Eigen::Vector3d& point) { points_.push_back(point); }

 private:
  std::vector<Eigen::Vector3d> points_;
};

// Axis-aligned bounding box of the cloud (empty box for an empty cloud).
Eigen::AlignedBox3d BoundingBox(const PointCloud& cloud);

// Removes non-finite points in place and returns how many were removed.
size_t RemoveNonFinite(PointCloud* cloud);

// Returns true when every coordinate of every point is finite.
bool AllFinite(const PointCloud& cloud);

// Applies `target_from_source` to every point.
PointCloud TransformCloud(const Eigen::Isometry3d& target_from_source,
                          const PointCloud& cloud);

}  // namespace mlndt
