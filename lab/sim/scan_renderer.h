#pragma once

// Rendering one scan: every ray of the sensor's pattern is cast from the
// sensor's pose at the ray's firing time, and a hit becomes a point
//   p = (r + sigma g) d      in the sensor frame at that time,
// r the exact range, d the ray's unit direction, g standard normal. A hit
// returns nothing when nearer than min_range_m, farther than max_range_m,
// at a grazing angle (|cos(incidence)| < min_cos_incidence) or dropped
// (probability dropout_probability); then every keep_every-th return is
// kept. The noise is along the ray only: no beam divergence, no mixed
// pixels at edges, no dependence of the noise on range or incidence.
//
// Motion within the scan: with `moving`, the sensor's pose at time tau
// after the stamp is P(tau) = P TwistToMotion(tau v) (v = the trajectory's
// velocity at that scan), so the points are skewed as a real sweep's are,
// and DeskewScan(v, times) (odometry/deskew.h) moves them into the frame at
// the stamp exactly. Without it every ray leaves from P.

#include <cstdint>
#include <vector>

#include "lab/sim/ray_caster.h"
#include "lab/sim/sensor_model.h"
#include "mlndt/common/types.h"

namespace mlndt {
namespace sim {

struct SimScan {
  // Each return in the sensor frame at its firing time, with noise [m].
  std::vector<Vector3d> points;
  std::vector<float> times_s;      // Firing time after the stamp [s].
  std::vector<uint16_t> channels;  // Laser (ring).
  // The exact hit in the world and the surface normal there, per point.
  std::vector<Vector3d> world_hits;
  std::vector<Vector3d> world_normals;
  size_t rays = 0;  // Rays cast.
};

struct ScanMotion {
  Isometry3d world_from_sensor = Isometry3d::Identity();  // At the stamp.
  Vector6d velocity = Vector6d::Zero();  // SimTrajectory::Velocity.
  bool moving = false;
};

// Deterministic for a given seed (the noise and dropouts are drawn from
// it, the same number of draws for every ray).
void RenderScan(const RayCaster& caster,
                const SensorModel& sensor,
                const std::vector<SensorRay>& rays,
                const ScanMotion& motion,
                uint64_t seed,
                SimScan* scan);

}  // namespace sim
}  // namespace mlndt
