#include "lab/sim/mesh_shapes.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace mlndt {
namespace sim {
namespace {

using Eigen::Vector3d;

// The 12 vertices and 20 faces of the unit icosahedron.
void Icosahedron(std::vector<Vector3d>* vertices,
                 std::vector<std::array<int, 3>>* faces) {
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  *vertices = {{-1, g, 0},
               {1, g, 0},
               {-1, -g, 0},
               {1, -g, 0},
               {0, -1, g},
               {0, 1, g},
               {0, -1, -g},
               {0, 1, -g},
               {g, 0, -1},
               {g, 0, 1},
               {-g, 0, -1},
               {-g, 0, 1}};
  for (Vector3d& v : *vertices) v.normalize();
  *faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
            {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
            {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
            {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
}

// One subdivision of a unit sphere mesh: each face into four.
void Subdivide(std::vector<Vector3d>* vertices,
               std::vector<std::array<int, 3>>* faces) {
  std::map<std::pair<int, int>, int> midpoints;
  const auto midpoint = [&](int a, int b) {
    const std::pair<int, int> key(std::min(a, b), std::max(a, b));
    const auto it = midpoints.find(key);
    if (it != midpoints.end()) return it->second;
    vertices->push_back(((*vertices)[a] + (*vertices)[b]).normalized());
    const int index = static_cast<int>(vertices->size()) - 1;
    midpoints.emplace(key, index);
    return index;
  };
  std::vector<std::array<int, 3>> finer;
  for (const auto& f : *faces) {
    const int ab = midpoint(f[0], f[1]);
    const int bc = midpoint(f[1], f[2]);
    const int ca = midpoint(f[2], f[0]);
    finer.push_back({f[0], ab, ca});
    finer.push_back({f[1], bc, ab});
    finer.push_back({f[2], ca, bc});
    finer.push_back({ab, bc, ca});
  }
  *faces = std::move(finer);
}

}  // namespace

void AddBox(const Vector3d& min, const Vector3d& max, TriangleMesh* mesh) {
  const auto corner = [&](int k) {
    return Vector3d((k & 1) ? max.x() : min.x(),
                    (k & 2) ? max.y() : min.y(),
                    (k & 4) ? max.z() : min.z());
  };
  // Faces by corner index (bit 0: x, bit 1: y, bit 2: z).
  const int faces[6][4] = {{0, 2, 3, 1},
                           {4, 5, 7, 6},
                           {0, 1, 5, 4},
                           {2, 6, 7, 3},
                           {0, 4, 6, 2},
                           {1, 3, 7, 5}};
  for (const auto& f : faces) {
    mesh->AddQuad(corner(f[0]), corner(f[1]), corner(f[2]), corner(f[3]));
  }
}

void AddYawedBox(const Vector3d& center,
                 const Vector3d& size,
                 double yaw,
                 TriangleMesh* mesh) {
  TriangleMesh box;
  AddBox(-size / 2.0, size / 2.0, &box);
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::AngleAxisd(yaw, Vector3d::UnitZ()).toRotationMatrix();
  pose.translation() = center;
  mesh->Append(box, pose);
}

void AddCylinder(const Vector3d& base,
                 double radius,
                 double height,
                 int segments,
                 TriangleMesh* mesh) {
  CHECK_GE(segments, 3);
  const Vector3d top = base + Vector3d(0, 0, height);
  for (int k = 0; k < segments; ++k) {
    const double a0 = 2.0 * M_PI * k / segments;
    const double a1 = 2.0 * M_PI * (k + 1) / segments;
    const Vector3d d0(radius * std::cos(a0), radius * std::sin(a0), 0.0);
    const Vector3d d1(radius * std::cos(a1), radius * std::sin(a1), 0.0);
    mesh->AddQuad(base + d0, base + d1, top + d1, top + d0);
    mesh->AddTriangle(top, top + d0, top + d1);
  }
}

void AddBlob(const Vector3d& center,
             const Vector3d& radii,
             int subdivisions,
             double jitter,
             SimRandom* random,
             TriangleMesh* mesh) {
  std::vector<Vector3d> vertices;
  std::vector<std::array<int, 3>> faces;
  Icosahedron(&vertices, &faces);
  for (int s = 0; s < subdivisions; ++s) Subdivide(&vertices, &faces);
  for (Vector3d& v : vertices) {
    const double factor = 1.0 + jitter * random->Uniform(-1.0, 1.0);
    v = center + factor * v.cwiseProduct(radii);
  }
  for (const auto& f : faces) {
    mesh->AddTriangle(vertices[f[0]], vertices[f[1]], vertices[f[2]]);
  }
}

void AddLeaves(const Vector3d& center,
               const Vector3d& radii,
               int count,
               double size,
               SimRandom* random,
               TriangleMesh* mesh) {
  for (int k = 0; k < count; ++k) {
    Vector3d u;
    do {
      u = Vector3d(random->Uniform(-1, 1),
                   random->Uniform(-1, 1),
                   random->Uniform(-1, 1));
    } while (u.squaredNorm() > 1.0);
    const Vector3d p = center + u.cwiseProduct(radii);
    Vector3d e1(random->Gaussian(), random->Gaussian(), random->Gaussian());
    Vector3d e2(random->Gaussian(), random->Gaussian(), random->Gaussian());
    e1 = e1.normalized() * size;
    e2 = (e2 - e2.dot(e1) / e1.squaredNorm() * e1).normalized() * size;
    mesh->AddTriangle(p, p + e1, p + 0.5 * e1 + e2);
  }
}

void AddHeightField(double x0,
                    double x1,
                    double y0,
                    double y1,
                    double cell,
                    const std::function<double(double, double)>& height,
                    TriangleMesh* mesh) {
  const int nx = std::max(1, static_cast<int>(std::ceil((x1 - x0) / cell)));
  const int ny = std::max(1, static_cast<int>(std::ceil((y1 - y0) / cell)));
  const auto at = [&](int i, int j) {
    const double x = x0 + (x1 - x0) * i / nx;
    const double y = y0 + (y1 - y0) * j / ny;
    return Vector3d(x, y, height(x, y));
  };
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < ny; ++j) {
      mesh->AddQuad(at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
    }
  }
}

void AddExtrudedProfile(const std::vector<Eigen::Vector2d>& profile,
                        double x0,
                        double x1,
                        TriangleMesh* mesh) {
  for (size_t k = 0; k + 1 < profile.size(); ++k) {
    const Eigen::Vector2d& a = profile[k];
    const Eigen::Vector2d& b = profile[k + 1];
    mesh->AddQuad(Vector3d(x0, a.x(), a.y()),
                  Vector3d(x1, a.x(), a.y()),
                  Vector3d(x1, b.x(), b.y()),
                  Vector3d(x0, b.x(), b.y()));
  }
}

}  // namespace sim
}  // namespace mlndt
