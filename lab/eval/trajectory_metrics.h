#pragma once

// Accuracy of an estimated trajectory against a reference trajectory: the
// absolute trajectory error (ATE) after an alignment, and the relative pose
// error (RPE) of motions over a fixed number of frames. Both take poses
// already paired up (trajectory_association.h): reference[k] and estimate[k]
// are world_from_sensor at the same instant, each in its own world frame.

#include <string>
#include <vector>

#include "lab/eval/statistics.h"
#include "lab/eval/umeyama.h"
#include "mlndt/common/types.h"

namespace mlndt {

// How the estimate is brought into the reference's world frame before the
// ATE is taken.
enum class TrajectoryAlignment {
  NONE,        // As given: the two world frames are the same.
  FIRST_POSE,  // estimate_k -> reference_0 estimate_0^-1 estimate_k.
  SE3,         // Umeyama rigid fit of the positions (umeyama.h).
  SIM3,        // Umeyama similarity fit (with scale: monocular odometry).
};

const char* TrajectoryAlignmentToString(TrajectoryAlignment alignment);
bool StringToTrajectoryAlignment(std::string value,
                                 TrajectoryAlignment* alignment);

struct AteOptions {
  TrajectoryAlignment alignment = TrajectoryAlignment::SE3;
};

// ATE: e_k = |t(reference_k) - A t(estimate_k)| [m], A the alignment.
struct AteSummary {
  // A: aligned positions are reference_from_estimate * t(estimate_k); its
  // scale is 1 unless SIM3.
  SimilarityTransform reference_from_estimate;
  std::vector<double> errors_m;  // e_k, one per pair.
  double rmse_m = 0.0;           // sqrt(sum e_k^2 / n).
  Stats errors;                  // Mean, median, max, ... of e_k [m].
};

// False with *error when the sizes differ, there are no poses, or the
// Umeyama fit fails (fewer than 3 poses, all at one position).
bool ComputeAte(const AteOptions& options,
                const std::vector<Isometry3d>& reference,
                const std::vector<Isometry3d>& estimate,
                AteSummary* summary,
                std::string* error);

struct RpeOptions {
  int delta = 1;  // Frames between the two poses of a relative motion; >= 1.
};

// RPE over pairs (k, k + delta): with the relative motions
// Q = reference_k^-1 reference_{k+delta} and P = estimate_k^-1
// estimate_{k+delta}, the error E = Q^-1 P has translation
// |t(E)| = |t(Q) - t(P)| [m] (TranslationErrorM) and rotation
// angle(R(E)) = angle(R(Q)^T R(P)) [deg] (RotationErrorRad). The translation
// is taken as |t(Q) - t(P)|, which equals |t(E)| for exact rotations and,
// unlike |t(E)|, does not change with the rounding of R(Q) in a file
// (KITTI's 10 digits move |t(E)| by ~1e-7 relative).
struct RpeSummary {
  Stats translation_m;
  Stats rotation_deg;
  double translation_rmse_m = 0.0;
  double rotation_rmse_deg = 0.0;
};

// False with *error when the sizes differ, delta < 1, or there are not more
// than delta poses.
bool ComputeRpe(const RpeOptions& options,
                const std::vector<Isometry3d>& reference,
                const std::vector<Isometry3d>& estimate,
                RpeSummary* summary,
                std::string* error);

}  // namespace mlndt
