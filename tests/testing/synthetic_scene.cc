#include "tests/testing/synthetic_scene.h"

#include <random>
#include <vector>

namespace mlndt {
namespace testing {
namespace {

// An axis-aligned rectangle: origin + u * [0, 1] + v * [0, 1].
struct Patch {
  Eigen::Vector3d origin, u, v;
  double area() const { return u.cross(v).norm(); }
};

std::vector<Patch> ScenePatches() {
  std::vector<Patch> patches;
  const Eigen::Vector3d ex(1, 0, 0), ey(0, 1, 0), ez(0, 0, 1);
  patches.push_back(
      {Eigen::Vector3d(-40, -20, 0), 80 * ex, 40 * ey});  // Ground.
  // Building rows on both sides, with recesses every 16 m.
  for (int side = -1; side <= 1; side += 2) {
    for (int b = 0; b < 5; ++b) {
      const double x0 = -40 + 16 * b;
      const double y = side * (12.0 + (b % 2) * 2.5);
      patches.push_back(
          {Eigen::Vector3d(x0, y, 0), 12 * ex, (8.0 + 2 * (b % 3)) * ez});
      patches.push_back(
          {Eigen::Vector3d(x0 + 12, y, 0), side * 4 * ey, 8 * ez});
    }
  }
  // Boxes (cars): four faces and a roof each.
  const double boxes[][2] = {{-25, -6}, {-8, 5}, {6, -7}, {22, 6}, {31, -5}};
  for (const auto& b : boxes) {
    const Eigen::Vector3d o(b[0], b[1], 0);
    patches.push_back({o, 4.5 * ex, 1.5 * ez});
    patches.push_back({o + 1.8 * ey, 4.5 * ex, 1.5 * ez});
    patches.push_back({o, 1.8 * ey, 1.5 * ez});
    patches.push_back({o + 4.5 * ex, 1.8 * ey, 1.5 * ez});
    patches.push_back({o + 1.5 * ez, 4.5 * ex, 1.8 * ey});
  }
  // Poles: thin vertical strips in two orientations.
  for (int p = 0; p < 8; ++p) {
    const Eigen::Vector3d o(-35 + 10 * p, (p % 2 ? 9.0 : -9.0), 0);
    patches.push_back({o, 0.3 * ex, 6 * ez});
    patches.push_back({o, 0.3 * ey, 6 * ez});
  }
  return patches;
}

}  // namespace

PointCloud StreetScene(int num_points, double noise_m, uint32_t seed) {
  const std::vector<Patch> patches = ScenePatches();
  std::vector<double> areas;
  for (const Patch& p : patches) areas.push_back(p.area());
  std::mt19937 rng(seed);
  std::discrete_distribution<size_t> pick(areas.begin(), areas.end());
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, noise_m);
  PointCloud cloud;
  cloud.Reserve(static_cast<size_t>(num_points));
  for (int i = 0; i < num_points; ++i) {
    const Patch& p = patches[pick(rng)];
    const Eigen::Vector3d point = p.origin + unit(rng) * p.u + unit(rng) * p.v;
    cloud.Add(point + Eigen::Vector3d(noise(rng), noise(rng), noise(rng)));
  }
  return cloud;
}

PointCloud Corridor(double half_length, int num_points, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> along(-half_length, half_length);
  std::uniform_real_distribution<double> up(0.0, 3.0), across(-2.0, 2.0);
  std::uniform_real_distribution<double> thickness(-0.01, 0.01);
  PointCloud cloud;
  cloud.Reserve(static_cast<size_t>(num_points));
  for (int i = 0; i < num_points; ++i) {
    const double x = along(rng), t = thickness(rng);
    switch (i % 3) {
      case 0:
        cloud.Add(Eigen::Vector3d(x, -2.0 + t, up(rng)));
        break;
      case 1:
        cloud.Add(Eigen::Vector3d(x, 2.0 + t, up(rng)));
        break;
      default:
        cloud.Add(Eigen::Vector3d(x, across(rng), t));
    }
  }
  return cloud;
}

PointCloud UniformBox(const Eigen::Vector3d& low,
                      const Eigen::Vector3d& high,
                      int n,
                      uint32_t seed) {
  std::mt19937 rng(seed);
  PointCloud cloud;
  for (int i = 0; i < n; ++i) {
    Eigen::Vector3d p;
    for (int a = 0; a < 3; ++a) {
      p(a) = std::uniform_real_distribution<double>(low(a), high(a))(rng);
    }
    cloud.Add(p);
  }
  return cloud;
}

PointCloud SlabCorridor(uint32_t seed) {
  PointCloud merged;
  for (const PointCloud& slab :
       {UniformBox({-30, -2.01, 0}, {30, -1.99, 3}, 15000, seed),
        UniformBox({-30, 1.99, 0}, {30, 2.01, 3}, 15000, seed + 10),
        UniformBox({-30, -2, -0.01}, {30, 2, 0.01}, 15000, seed + 20)}) {
    for (const Eigen::Vector3d& p : slab.points()) merged.Add(p);
  }
  return merged;
}

}  // namespace testing
}  // namespace mlndt
