#include "lab/sim/triangle_mesh.h"

namespace mlndt {
namespace sim {

void TriangleMesh::AddTriangle(const Eigen::Vector3d& a,
                               const Eigen::Vector3d& b,
                               const Eigen::Vector3d& c) {
  const auto first = static_cast<uint32_t>(vertices.size());
  vertices.push_back(a.cast<float>());
  vertices.push_back(b.cast<float>());
  vertices.push_back(c.cast<float>());
  triangles.push_back({first, first + 1, first + 2});
}

void TriangleMesh::AddQuad(const Eigen::Vector3d& a,
                           const Eigen::Vector3d& b,
                           const Eigen::Vector3d& c,
                           const Eigen::Vector3d& d) {
  const auto first = static_cast<uint32_t>(vertices.size());
  for (const Eigen::Vector3d* v : {&a, &b, &c, &d}) {
    vertices.push_back(v->cast<float>());
  }
  triangles.push_back({first, first + 1, first + 2});
  triangles.push_back({first, first + 2, first + 3});
}

void TriangleMesh::Append(const TriangleMesh& other,
                          const Eigen::Isometry3d& transform) {
  const auto offset = static_cast<uint32_t>(vertices.size());
  const Eigen::Isometry3f t = transform.cast<float>();
  for (const Eigen::Vector3f& v : other.vertices) vertices.push_back(t * v);
  for (const auto& tri : other.triangles) {
    triangles.push_back({tri[0] + offset, tri[1] + offset, tri[2] + offset});
  }
}

Eigen::Vector3d TriangleNormal(const TriangleMesh& mesh, size_t k) {
  const auto& tri = mesh.triangles.at(k);
  const Eigen::Vector3d a = mesh.vertices[tri[0]].cast<double>();
  const Eigen::Vector3d b = mesh.vertices[tri[1]].cast<double>();
  const Eigen::Vector3d c = mesh.vertices[tri[2]].cast<double>();
  const Eigen::Vector3d n = (b - a).cross(c - a);
  const double norm = n.norm();
  return norm > 0.0 ? Eigen::Vector3d(n / norm) : Eigen::Vector3d::Zero();
}

Eigen::AlignedBox3d MeshBounds(const TriangleMesh& mesh) {
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3f& v : mesh.vertices) box.extend(v.cast<double>());
  return box;
}

}  // namespace sim
}  // namespace mlndt
