#pragma once

// Casting rays against a TriangleMesh with Embree 3 (Debian's
// libembree-dev). Each ray returns the distance to the first triangle it
// meets, from either side, and that triangle's normal. Debian builds Embree
// with ray masks, so every ray is cast with mask 0xFFFFFFFF (a ray with mask
// 0 passes through every geometry). The BVH is built on one thread, so the
// same mesh gives the same hits on every run.

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "lab/sim/triangle_mesh.h"

namespace mlndt {
namespace sim {

struct CastRay {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();  // Unit length.
  double max_range_m = 100.0;  // Hits farther than this are misses.
};

struct RayHit {
  bool hit = false;
  double range_m = 0.0;  // Along the unit direction; set when hit.
  // Unit normal of the triangle hit, turned to face the ray's origin.
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  uint32_t triangle = 0;  // Index into the mesh's triangles.
};

class RayCaster {
 public:
  // Null with *error when the mesh is empty, holds an index out of range or
  // a non-finite vertex, or Embree fails (its error code in the message).
  static std::unique_ptr<RayCaster> Create(const TriangleMesh& mesh,
                                           std::string* error);
  ~RayCaster();
  RayCaster(const RayCaster&) = delete;
  RayCaster& operator=(const RayCaster&) = delete;

  // One hit per ray, in order (*hits resized).
  void Cast(const std::vector<CastRay>& rays, std::vector<RayHit>* hits) const;
  RayHit Cast(const CastRay& ray) const;

 private:
  RayCaster() = default;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sim
}  // namespace mlndt
