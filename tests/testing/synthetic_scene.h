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

}  // namespace testing
}  // namespace mlndt
