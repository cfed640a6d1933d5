#pragma once

// Which directions of a pair's pose the scene leaves free. Two sources:
//  1. The scene's own symmetry (Scene::free_translations_world: a corridor
//     or tunnel of constant section is the same after any shift along its
//     axis), exact by construction.
//  2. What the pair actually sees: the Fisher information of the pose from
//     the exact (noise-free) surfaces seen by both scans. Each point p of
//     scan j seen from scan i, with the surface normal n there (both in the
//     reference frame i), constrains the left perturbation (dt, dw) of
//     reference_from_input through n.(dt + dw x p), with the sensor's range
//     noise sigma:
//       H = sum_p J^T J / sigma^2,   J = [n^T, (p x n)^T].
//     In units of the success tolerance (D = diag(tol_m I, tol_rad I)), the
//     Cramér-Rao bound of the pose's standard deviation along an
//     eigenvector v of D H D is 1 / sqrt(lambda). A direction is free when
//     that bound exceeds the tolerance (lambda < 1): no estimator could place
//     the pose within tolerance along it from these surfaces.
// Free directions are written as unit vectors of the pose vector (tx, ty,
// tz [m], alpha, beta, gamma [rad]; pose.h) of reference_from_input at the
// truth. A direction of source 2 that source 1 already names is not
// repeated.

#include <vector>

#include "lab/sim/ray_caster.h"
#include "lab/sim/scan_renderer.h"
#include "lab/sim/scene.h"
#include "lab/sim/sensor_model.h"
#include "mlndt/common/types.h"

namespace mlndt {
namespace sim {

struct PairConstraintOptions {
  double tolerance_m = 0.2;  // The suite's default success tolerance.
  double tolerance_deg = 1.0;
  // A point of scan j counts as seen from scan i when the ray from sensor i
  // towards it, inside sensor i's field of view and range, first meets a
  // surface within this of it [m].
  double visibility_m = 0.05;
  size_t max_points = 20000;  // Evenly subsampled beyond this (weighted).
};

struct PairConstraints {
  std::vector<Vector6d> free_directions;  // Unit pose-vector directions.
  size_t shared_points = 0;               // Points of scan j seen from scan i.
  // The Cramér-Rao bound along the weakest direction, in tolerance units
  // (infinite without shared points), and that direction.
  double weakest_std = 0.0;
  Vector6d weakest_direction = Vector6d::Zero();
};

// `input` is scan j, rendered from `world_from_input`'s trajectory (its
// world_hits and world_normals are read).
PairConstraints AnalysePairConstraints(const PairConstraintOptions& options,
                                       const RayCaster& caster,
                                       const SensorModel& sensor,
                                       const Scene& scene,
                                       const Isometry3d& world_from_reference,
                                       const Isometry3d& world_from_input,
                                       const SimScan& input);

}  // namespace sim
}  // namespace mlndt
