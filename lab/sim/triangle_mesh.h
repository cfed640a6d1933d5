#pragma once

// A triangle soup: the simulator's scene geometry. Triangles need not share
// vertices, be closed or be consistently oriented; a ray hits either side.
// Vertices are float32, as the ray caster (Embree) stores them.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <vector>

namespace mlndt {
namespace sim {

struct TriangleMesh {
  std::vector<Eigen::Vector3f> vertices;           // [m].
  std::vector<std::array<uint32_t, 3>> triangles;  // Indices into vertices.

  size_t num_triangles() const { return triangles.size(); }
  bool empty() const { return triangles.empty(); }

  void AddTriangle(const Eigen::Vector3d& a,
                   const Eigen::Vector3d& b,
                   const Eigen::Vector3d& c);
  // Two triangles a-b-c and a-c-d (a planar quad in this order).
  void AddQuad(const Eigen::Vector3d& a,
               const Eigen::Vector3d& b,
               const Eigen::Vector3d& c,
               const Eigen::Vector3d& d);
  // Appends `other` with every vertex moved by `transform`.
  void Append(
      const TriangleMesh& other,
      const Eigen::Isometry3d& transform = Eigen::Isometry3d::Identity());
};

// The unit normal of triangle k (right-handed order of its vertices); zero
// for a degenerate triangle.
Eigen::Vector3d TriangleNormal(const TriangleMesh& mesh, size_t k);

// The axis-aligned box of the vertices (empty box without vertices).
Eigen::AlignedBox3d MeshBounds(const TriangleMesh& mesh);

}  // namespace sim
}  // namespace mlndt
