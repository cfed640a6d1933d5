#include "lab/sim/scan_renderer.h"

#include <glog/logging.h>

#include <cmath>

#include "lab/sim/sim_random.h"
#include "mlndt/odometry/motion_prediction.h"

namespace mlndt {
namespace sim {

void RenderScan(const RayCaster& caster,
                const SensorModel& sensor,
                const std::vector<SensorRay>& rays,
                const ScanMotion& motion,
                uint64_t seed,
                SimScan* scan) {
  CHECK(scan != nullptr);
  *scan = SimScan();
  scan->rays = rays.size();
  const ReturnOptions& returns = sensor.returns;
  SimRandom random(seed, "returns");
  size_t returned = 0;
  for (const SensorRay& ray : rays) {
    // Draw the same numbers for every ray, hit or not.
    const double dropout = random.Uniform();
    const double noise = random.Gaussian();
    const Isometry3d pose =
        motion.moving ? Isometry3d(motion.world_from_sensor *
                                   TwistToMotion(ray.time_s * motion.velocity))
                      : motion.world_from_sensor;
    CastRay cast;
    cast.origin = pose.translation();
    cast.direction = pose.linear() * ray.direction;
    cast.max_range_m = returns.max_range_m;
    const RayHit hit = caster.Cast(cast);
    if (!hit.hit || hit.range_m < returns.min_range_m) continue;
    if (std::abs(hit.normal.dot(cast.direction)) < returns.min_cos_incidence) {
      continue;
    }
    if (dropout < returns.dropout_probability) continue;
    if (returned++ % static_cast<size_t>(returns.keep_every) != 0) continue;
    const double range = hit.range_m + returns.range_sigma_m * noise;
    scan->points.push_back(range * ray.direction);
    scan->times_s.push_back(static_cast<float>(ray.time_s));
    scan->channels.push_back(static_cast<uint16_t>(ray.channel));
    scan->world_hits.push_back(cast.origin + hit.range_m * cast.direction);
    scan->world_normals.push_back(hit.normal);
  }
}

}  // namespace sim
}  // namespace mlndt
