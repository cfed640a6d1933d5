// Ray casting with Embree: ranges against planes and boxes equal the
// analytic ones (so Debian's masked Embree hits at all), normals face the
// ray, misses beyond the range, bad meshes refused.

#include "lab/sim/ray_caster.h"

#include <gtest/gtest.h>

#include <cmath>

#include "lab/sim/mesh_shapes.h"

namespace mlndt {
namespace sim {
namespace {

using Eigen::Vector3d;

TEST(RayCaster, RangeToAPlaneIsTheAnalyticOne) {
  // The plane x = 7 (a 200 m square).
  TriangleMesh mesh;
  mesh.AddQuad(Vector3d(7, -100, -100),
               Vector3d(7, 100, -100),
               Vector3d(7, 100, 100),
               Vector3d(7, -100, 100));
  std::string error;
  const auto caster = RayCaster::Create(mesh, &error);
  ASSERT_NE(caster, nullptr) << error;
  for (const double elevation_deg : {-40.0, -10.0, 0.0, 3.0, 25.0}) {
    for (const double azimuth_deg : {-60.0, -5.0, 0.0, 30.0, 70.0}) {
      const double a = azimuth_deg * M_PI / 180.0;
      const double e = elevation_deg * M_PI / 180.0;
      CastRay ray;
      ray.origin = Vector3d(1.0, 0.5, -0.25);
      ray.direction = Vector3d(
          std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e));
      ray.max_range_m = 200.0;
      const RayHit hit = caster->Cast(ray);
      ASSERT_TRUE(hit.hit) << azimuth_deg << " " << elevation_deg;
      // (7 - 1) / d.x.
      EXPECT_NEAR(hit.range_m, 6.0 / ray.direction.x(), 2e-5);
      EXPECT_NEAR(hit.normal.x(), -1.0, 1e-6);  // Faces the origin.
    }
  }
  CastRay away;
  away.origin = Vector3d(1, 0, 0);
  away.direction = Vector3d(-1, 0, 0);
  EXPECT_FALSE(caster->Cast(away).hit);
  CastRay short_ray;
  short_ray.origin = Vector3d(1, 0, 0);
  short_ray.max_range_m = 5.9;  // The plane is 6 m away.
  EXPECT_FALSE(caster->Cast(short_ray).hit);
}

TEST(RayCaster, InsideABoxEveryRayHitsTheNearestWall) {
  TriangleMesh mesh;
  const Vector3d min(-2, -3, -1), max(4, 5, 2.5);
  AddBox(min, max, &mesh);
  std::string error;
  const auto caster = RayCaster::Create(mesh, &error);
  ASSERT_NE(caster, nullptr) << error;
  const Vector3d origin(0.3, -0.2, 0.4);
  std::vector<CastRay> rays;
  for (int k = 0; k < 500; ++k) {
    const double z = -1.0 + 2.0 * (k + 0.5) / 500.0;
    const double phi = k * 2.399963;  // Golden angle: a spiral on the sphere.
    CastRay ray;
    ray.origin = origin;
    ray.direction = Vector3d(std::sqrt(1 - z * z) * std::cos(phi),
                             std::sqrt(1 - z * z) * std::sin(phi),
                             z);
    rays.push_back(ray);
  }
  std::vector<RayHit> hits;
  caster->Cast(rays, &hits);
  ASSERT_EQ(hits.size(), rays.size());
  for (size_t k = 0; k < rays.size(); ++k) {
    const Vector3d& d = rays[k].direction;
    double expected = std::numeric_limits<double>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
      if (d(axis) == 0.0) continue;
      const double wall = d(axis) > 0 ? max(axis) : min(axis);
      expected = std::min(expected, (wall - origin(axis)) / d(axis));
    }
    ASSERT_TRUE(hits[k].hit) << k;
    EXPECT_NEAR(hits[k].range_m, expected, 1e-5) << k;
    EXPECT_LT(hits[k].normal.dot(d), 0.0) << k;
  }
}

TEST(RayCaster, RefusesEmptyAndBrokenMeshes) {
  std::string error;
  EXPECT_EQ(RayCaster::Create(TriangleMesh(), &error), nullptr);
  EXPECT_NE(error.find("no triangles"), std::string::npos) << error;
  TriangleMesh broken;
  broken.AddTriangle(Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(0, 1, 0));
  broken.triangles.push_back({0, 1, 7});
  EXPECT_EQ(RayCaster::Create(broken, &error), nullptr);
  EXPECT_NE(error.find("out of range"), std::string::npos) << error;
  TriangleMesh nan;
  nan.AddTriangle(Vector3d(0, 0, NAN), Vector3d(1, 0, 0), Vector3d(0, 1, 0));
  EXPECT_EQ(RayCaster::Create(nan, &error), nullptr);
  EXPECT_NE(error.find("not finite"), std::string::npos) << error;
}

}  // namespace
}  // namespace sim
}  // namespace mlndt
