#pragma once

// Seeded synthetic scenes for registration tests: a street-like scene of a
// ground plane, two building rows with recesses, boxes (parked cars) and
// poles, sampled uniformly on the surfaces with Gaussian noise. Two calls
// with different seeds give two different samplings of the same surfaces,
// like two scans of one place.

#include <cstdint>

#include "mlndt/cloud/point_cloud.h"

namespace mlndt {
namespace testing {

// `num_points` samples with `noise_m` standard deviation, in the scene frame
// (x along the street, z up), spanning about 80 x 40 x 10 m.
PointCloud StreetScene(int num_points, double noise_m, uint32_t seed);

// Issue 22's corridor: two walls 4 m apart and 3 m high and the floor
// between them, x from -half_length to +half_length, `num_points` uniform
// samples (a third on each surface) 1 cm thick. Nothing fixes x.
PointCloud Corridor(double half_length, int num_points, uint32_t seed);

// `n` uniform samples of the box [low, high] (a slab when one side is thin).
PointCloud UniformBox(const Eigen::Vector3d& low,
                      const Eigen::Vector3d& high,
                      int n,
                      uint32_t seed);

// Corridor's surfaces as three slabs of UniformBox, 15000 samples each
// (seeds seed, seed + 10, seed + 20), x in [-30, 30]: x is free.
PointCloud SlabCorridor(uint32_t seed);

}  // namespace testing
}  // namespace mlndt
