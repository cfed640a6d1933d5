#include "lab/sim/handheld_trajectory.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "lab/sim/sim_random.h"
#include "mlndt/common/pose.h"

namespace mlndt {
namespace sim {
namespace {

// Where the carrier is: arc length along the path and offset to its left.
struct Place {
  double s = 0.0;
  double lateral = 0.0;
};

double WrapAngle(double a) { return std::remainder(a, 2.0 * M_PI); }

// The direction a walker looks: towards the path's point `lookahead` m
// ahead (smooths the path's corners), the tangent at its end.
double PathYaw(const ScenePath& path, double s, double lookahead) {
  Vector3d ahead = path.PointAt(s + lookahead) - path.PointAt(s);
  if (ahead.head<2>().norm() < 0.1 * lookahead) ahead = path.TangentAt(s);
  return std::atan2(ahead.y(), ahead.x());
}

// One step of `length` m: forward (60 %), sideways (25 %) or backward,
// relative to the path, kept on the path and within its lateral room.
Place NextPlace(const ScenePath& path,
                const Place& place,
                double length,
                SimRandom* random) {
  const double u = random->Uniform();
  double angle = random->Uniform(-M_PI / 3.0, M_PI / 3.0);
  if (u >= 0.6 && u < 0.85) {
    angle = random->Sign() * M_PI / 2.0 + random->Uniform(-0.35, 0.35);
  } else if (u >= 0.85) {
    angle = M_PI + random->Uniform(-0.5, 0.5);
  }
  double ds = length * std::cos(angle);
  double dl = length * std::sin(angle);
  if (place.s + ds < 0.0 || place.s + ds > path.Length()) ds = -ds;
  const double room = path.lateral_half_width_m;
  if (std::abs(place.lateral + dl) > room) dl = -dl;
  Place next;
  next.s = std::clamp(place.s + ds, 0.0, path.Length());
  next.lateral = std::clamp(place.lateral + dl, -room, room);
  return next;
}

// The next orientation: `current` turned by `angle` about an axis near
// the sensor's vertical, drawn until the sensor stays within the tilt and
// heading limits (the draw closest to them after 32 tries).
Matrix3d NextRotation(const HandheldTrajectoryOptions& options,
                      const Matrix3d& current,
                      double angle,
                      double path_yaw,
                      SimRandom* random) {
  const double max_tilt = options.max_tilt_deg * kDegToRad;
  const double max_heading = options.max_heading_offset_deg * kDegToRad;
  const double offset = WrapAngle(YawPitchRoll(current).x() - path_yaw);
  Matrix3d best = current;
  double best_excess = std::numeric_limits<double>::infinity();
  for (int attempt = 0; attempt < 32; ++attempt) {
    // Turn back towards the path's direction when more than half the
    // allowed offset away, else either way.
    double sign = random->Sign();
    if (std::abs(offset) > 0.5 * max_heading) sign = offset > 0 ? -1.0 : 1.0;
    const Vector3d axis(options.shake * random->Gaussian(),
                        options.shake * random->Gaussian(),
                        sign);
    const Matrix3d next =
        current *
        Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
    const Vector3d ypr = YawPitchRoll(next);
    const double excess =
        std::max({0.0,
                  std::abs(ypr.y()) - max_tilt,
                  std::abs(ypr.z()) - max_tilt,
                  std::abs(WrapAngle(ypr.x() - path_yaw)) - max_heading});
    if (excess < best_excess) {
      best = next;
      best_excess = excess;
    }
    if (excess == 0.0) break;
  }
  return best;
}

}  // namespace

bool HandheldTrajectoryOptions::IsValid(std::string* error) const {
  if (!(min_step_m > 0.0 && max_step_m >= min_step_m && max_step_m <= 10.0 &&
        min_rotation_deg >= 0.0 && max_rotation_deg >= min_rotation_deg &&
        max_rotation_deg <= 90.0 && shake >= 0.0 && max_tilt_deg > 0.0 &&
        max_tilt_deg <= 45.0 && max_heading_offset_deg > 0.0 &&
        max_heading_offset_deg <= 180.0 && lookahead_m > 0.0 &&
        min_height_m >= 0.0 && max_height_m >= min_height_m &&
        scan_interval_s > 0.0)) {
    *error =
        "hand-held trajectory: need 0 < min_step_m <= max_step_m <= 10, 0 <= "
        "min_rotation_deg <= max_rotation_deg <= 90, shake >= 0, tilt in (0, "
        "45], heading offset in (0, 180], lookahead_m > 0, 0 <= min_height_m "
        "<= max_height_m, "
        "scan_interval_s > 0";
    return false;
  }
  return true;
}

bool MakeHandheldTrajectory(const HandheldTrajectoryOptions& options,
                            const ScenePath& path,
                            int num_scans,
                            uint64_t seed,
                            SimTrajectory* trajectory,
                            std::string* error) {
  if (!options.IsValid(error)) return false;
  const double needed = num_scans * options.max_step_m;
  if (num_scans < 1 || path.points.size() < 2 || path.Length() < needed) {
    *error = "hand-held trajectory: " + std::to_string(num_scans) +
             " scans need a path of " + std::to_string(needed) + " m, the " +
             "scene's is " + std::to_string(path.Length()) + " m";
    return false;
  }
  SimRandom random(seed, "handheld_trajectory");
  *trajectory = SimTrajectory();
  trajectory->kind = "handheld";
  Place place;
  place.s = random.Uniform(0.0, path.Length() - needed);
  place.lateral = random.Uniform(-1.0, 1.0) * path.lateral_half_width_m;
  const double height =
      random.Uniform(options.min_height_m, options.max_height_m);
  const double start = random.Uniform(0.0, 1000.0);
  const double tilt = 0.5 * options.max_tilt_deg * kDegToRad;
  const double heading = 0.5 * options.max_heading_offset_deg * kDegToRad;
  Matrix3d rotation =
      PoseFromYawPitchRoll(Vector3d::Zero(),
                           PathYaw(path, place.s, options.lookahead_m) +
                               random.Uniform(-heading, heading),
                           random.Uniform(-tilt, tilt),
                           random.Uniform(-tilt, tilt))
          .linear();
  for (int k = 0; k < num_scans; ++k) {
    if (k > 0) {
      place = NextPlace(path,
                        place,
                        random.Uniform(options.min_step_m, options.max_step_m),
                        &random);
      const double angle =
          random.Uniform(options.min_rotation_deg, options.max_rotation_deg) *
          kDegToRad;
      rotation = NextRotation(options,
                              rotation,
                              angle,
                              PathYaw(path, place.s, options.lookahead_m),
                              &random);
    }
    const Vector3d t = path.TangentAt(place.s);
    const Vector3d left = Vector3d(-t.y(), t.x(), 0.0).normalized();
    Isometry3d pose = Isometry3d::Identity();
    pose.linear() = rotation;
    pose.translation() = path.PointAt(place.s) + place.lateral * left +
                         Vector3d(0, 0, height + random.Uniform(-0.05, 0.05));
    trajectory->world_from_sensor.push_back(pose);
    trajectory->stamps_s.push_back(start + k * options.scan_interval_s);
  }
  return true;
}

}  // namespace sim
}  // namespace mlndt
