#pragma once

// One registration of mlndt_bench: what a method returns (BenchEstimate)
// and the run scored against the pair's reference (BenchRun).

#include <cstdint>
#include <limits>

#include "mlndt/common/types.h"

namespace mlndt {

// What a method reports for one pair, before it is scored.
struct BenchEstimate {
  Isometry3d reference_from_input = Isometry3d::Identity();
  // The method's own verdict (mlndt: RegistrationSummary::IsSolutionUsable;
  // PCL: hasConverged()).
  bool usable = false;
  // Stopped on its convergence test, not on an iteration cap.
  bool converged = false;
  // The pose covariance (mlndt); zero: none.
  Matrix6d covariance = Matrix6d::Zero();
  double time_ms = 0.0;   // Everything after loading.
  double align_ms = 0.0;  // PCL only: align() alone.
  int iterations = 0;
  // mlndt: RegistrationSummary::point_iterations (samples evaluated over all
  // iterations, stages and attempts: the solve's work free of machine
  // noise); -1: not counted (PCL).
  int64_t point_iterations = -1;
  double score = std::numeric_limits<double>::quiet_NaN();  // Eq. (10).
};

// The result of one registration.
struct BenchRun {
  double time_ms = 0.0;
  double align_ms = 0.0;  // PCL only: align() alone.
  int iterations = 0;
  int64_t point_iterations = -1;  // As BenchEstimate's; -1: not counted.
  double score = std::numeric_limits<double>::quiet_NaN();
  double translation_error_m = 0.0;
  double rotation_error_deg = 0.0;
  // Stopped on its convergence test, not on an iteration cap.
  bool converged = false;
  bool success = false;
  // e^T P^-1 e against the reference, e the pose-vector difference estimate
  // - reference and P the covariance (lab/eval/nees.h; 6 when P is
  // consistent with the errors); NaN when the run is not usable or has no
  // covariance (PCL).
  double nees = std::numeric_limits<double>::quiet_NaN();
};

// A run succeeds when it is usable and both errors are below these.
struct BenchThresholds {
  double max_translation_error_m = 0.2;
  double max_rotation_error_deg = 1.0;
};

// `estimate` scored against `truth` (reference_from_input).
BenchRun ScoreEstimate(const BenchEstimate& estimate,
                       const Isometry3d& truth,
                       const BenchThresholds& thresholds);

}  // namespace mlndt
