#pragma once

// Shapes the procedural scenes are built from, each appended to a
// TriangleMesh as triangles. Lengths in metres, angles in radians; z is up.

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "lab/sim/sim_random.h"
#include "lab/sim/triangle_mesh.h"

namespace mlndt {
namespace sim {

// The six faces of the axis-aligned box [min, max].
void AddBox(const Eigen::Vector3d& min,
            const Eigen::Vector3d& max,
            TriangleMesh* mesh);

// A box of `size` centred on `center` (its base at center.z - size.z / 2),
// turned by `yaw` about the vertical through its centre.
void AddYawedBox(const Eigen::Vector3d& center,
                 const Eigen::Vector3d& size,
                 double yaw,
                 TriangleMesh* mesh);

// A vertical cylinder standing on `base` (the centre of its bottom), as a
// prism of `segments` >= 3 side quads with a top cap.
void AddCylinder(const Eigen::Vector3d& base,
                 double radius,
                 double height,
                 int segments,
                 TriangleMesh* mesh);

// A closed, star-shaped blob (tree crowns, bushes, rocks): an icosahedron
// subdivided `subdivisions` times (20 * 4^s triangles), scaled to the
// ellipsoid of semi-axes `radii` about `center`, each vertex moved
// radially by a factor in [1 - jitter, 1 + jitter].
void AddBlob(const Eigen::Vector3d& center,
             const Eigen::Vector3d& radii,
             int subdivisions,
             double jitter,
             SimRandom* random,
             TriangleMesh* mesh);

// `count` small triangles of side about `size`, randomly placed and turned
// inside the ellipsoid of semi-axes `radii` about `center` (foliage).
void AddLeaves(const Eigen::Vector3d& center,
               const Eigen::Vector3d& radii,
               int count,
               double size,
               SimRandom* random,
               TriangleMesh* mesh);

// The surface z = height(x, y) over [x0, x1] x [y0, y1] on a grid of
// square cells of about `cell` (two triangles per cell).
void AddHeightField(double x0,
                    double x1,
                    double y0,
                    double y1,
                    double cell,
                    const std::function<double(double, double)>& height,
                    TriangleMesh* mesh);

// A cross-section extruded along x from x0 to x1: each segment of the
// polyline `profile` (points (y, z)) becomes one long quad. A tube of
// constant section, the same everywhere along x (corridors, tunnels).
void AddExtrudedProfile(const std::vector<Eigen::Vector2d>& profile,
                        double x0,
                        double x1,
                        TriangleMesh* mesh);

}  // namespace sim
}  // namespace mlndt
