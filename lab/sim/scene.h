#pragma once

// A simulated scene: its triangles, where a sensor may travel in it, and
// the directions in which the scene is the same everywhere (a straight
// corridor or tunnel of constant section leaves the pose free along its
// axis). Built from a seed by the scene builders (scenes.h).

#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

#include "lab/sim/triangle_mesh.h"

namespace mlndt {
namespace sim {

// A polyline on the walking or driving surface (z is that surface's
// height), along which trajectories travel, and how far off it sideways
// they may go.
struct ScenePath {
  std::vector<Eigen::Vector3d> points;  // At least 2, consecutive distinct.
  double lateral_half_width_m = 0.0;

  double Length() const;
  // The point at arc length s (clamped to [0, Length()]).
  Eigen::Vector3d PointAt(double s) const;
  // The unit direction of the segment at arc length s.
  Eigen::Vector3d TangentAt(double s) const;
};

struct Scene {
  std::string kind;  // "street", "corridor", ...
  uint64_t seed = 0;
  TriangleMesh mesh;
  ScenePath path;
  // Unit world directions along which translating the whole scene maps it
  // onto itself within every sensor's range (empty: none).
  std::vector<Eigen::Vector3d> free_translations_world;
  // The random parameters drawn for this seed, by name (for
  // simulation.json).
  std::map<std::string, double> parameters;
};

}  // namespace sim
}  // namespace mlndt
