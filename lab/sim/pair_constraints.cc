#include "lab/sim/pair_constraints.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

#include "mlndt/common/pose.h"
#include "mlndt/odometry/motion_prediction.h"

namespace mlndt {
namespace sim {
namespace {

// Whether sensor i (at world_from_sensor) sees the world point `hit` with
// normal `normal` directly.
bool Sees(const PairConstraintOptions& options,
          const RayCaster& caster,
          const SensorModel& sensor,
          const Isometry3d& world_from_sensor,
          const Vector3d& hit,
          const Vector3d& normal) {
  const Vector3d local = world_from_sensor.inverse() * hit;
  const double range = local.norm();
  const ReturnOptions& returns = sensor.returns;
  if (range < returns.min_range_m || range > returns.max_range_m) return false;
  if (!SensorCovers(sensor, local / range)) return false;
  CastRay ray;
  ray.origin = world_from_sensor.translation();
  ray.direction = (hit - ray.origin) / range;
  if (std::abs(normal.dot(ray.direction)) < returns.min_cos_incidence) {
    return false;
  }
  ray.max_range_m = range + options.visibility_m;
  const RayHit seen = caster.Cast(ray);
  return seen.hit && std::abs(seen.range_m - range) <= options.visibility_m;
}

// d(pose vector) / d(left perturbation (dt, dw)) of `transform`, by
// central differences.
Matrix6d PoseVectorJacobian(const Isometry3d& transform) {
  const double h = 1e-6;
  Matrix6d jacobian;
  for (int k = 0; k < 6; ++k) {
    Vector6d delta = Vector6d::Zero();
    delta(k) = h;
    const auto perturbed = [&](double sign) {
      Vector6d twist = sign * delta;
      Isometry3d left = Isometry3d::Identity();
      left.linear() = TwistToMotion(twist).linear();
      left.translation() = twist.head<3>();
      return IsometryToPoseVector(left * transform);
    };
    jacobian.col(k) = (perturbed(1.0) - perturbed(-1.0)) / (2.0 * h);
  }
  return jacobian;
}

}  // namespace

PairConstraints AnalysePairConstraints(const PairConstraintOptions& options,
                                       const RayCaster& caster,
                                       const SensorModel& sensor,
                                       const Scene& scene,
                                       const Isometry3d& world_from_reference,
                                       const Isometry3d& world_from_input,
                                       const SimScan& input) {
  PairConstraints result;
  const Isometry3d reference_from_world = world_from_reference.inverse();
  const size_t n = input.world_hits.size();
  const size_t stride =
      std::max<size_t>(1, (n + options.max_points - 1) / options.max_points);
  const double sigma = std::max(sensor.returns.range_sigma_m, 0.005);
  Matrix6d information = Matrix6d::Zero();
  for (size_t k = 0; k < n; k += stride) {
    if (!Sees(options,
              caster,
              sensor,
              world_from_reference,
              input.world_hits[k],
              input.world_normals[k])) {
      continue;
    }
    result.shared_points += stride;
    const Vector3d p = reference_from_world * input.world_hits[k];
    const Vector3d normal =
        reference_from_world.linear() * input.world_normals[k];
    Vector6d j;
    j << normal, p.cross(normal);
    information += (stride / (sigma * sigma)) * j * j.transpose();
  }
  Vector6d scale;
  scale << Vector3d::Constant(options.tolerance_m),
      Vector3d::Constant(options.tolerance_deg * kDegToRad);
  const Matrix6d scaled = scale.asDiagonal() * information * scale.asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Matrix6d> eigen(scaled);
  const Isometry3d reference_from_input =
      reference_from_world * world_from_input;
  const Matrix6d to_pose_vector = PoseVectorJacobian(reference_from_input);
  const auto direction = [&](int k) -> Vector6d {
    return (to_pose_vector * scale.asDiagonal() * eigen.eigenvectors().col(k))
        .normalized();
  };
  const double weakest = std::max(eigen.eigenvalues()(0), 0.0);
  result.weakest_std = weakest > 0.0 ? 1.0 / std::sqrt(weakest)
                                     : std::numeric_limits<double>::infinity();
  result.weakest_direction = direction(0);
  for (const Vector3d& axis : scene.free_translations_world) {
    Vector6d free = Vector6d::Zero();
    free.head<3>() = (reference_from_world.linear() * axis).normalized();
    result.free_directions.push_back(free);
  }
  for (int k = 0; k < 6 && eigen.eigenvalues()(k) < 1.0; ++k) {
    Vector6d free = direction(k);
    for (const Vector6d& known : result.free_directions) {
      free -= free.dot(known) * known;
    }
    if (free.norm() > 0.5) result.free_directions.push_back(free.normalized());
  }
  return result;
}

}  // namespace sim
}  // namespace mlndt
