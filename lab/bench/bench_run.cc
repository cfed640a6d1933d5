#include "lab/bench/bench_run.h"

#include "lab/eval/nees.h"
#include "mlndt/common/pose.h"

namespace mlndt {

BenchRun ScoreEstimate(const BenchEstimate& estimate,
                       const Isometry3d& truth,
                       const BenchThresholds& thresholds) {
  BenchRun r;
  r.translation_error_m =
      TranslationErrorM(truth, estimate.reference_from_input);
  r.rotation_error_deg =
      RotationErrorRad(truth, estimate.reference_from_input) * kRadToDeg;
  r.success = estimate.usable &&
              r.translation_error_m < thresholds.max_translation_error_m &&
              r.rotation_error_deg < thresholds.max_rotation_error_deg;
  if (estimate.usable && estimate.covariance.allFinite() &&
      estimate.covariance.trace() > 0.0) {
    const Vector6d e = IsometryToPoseVector(estimate.reference_from_input) -
                       IsometryToPoseVector(truth);
    r.nees = Nees(e, estimate.covariance);
  }
  r.time_ms = estimate.time_ms;
  r.align_ms = estimate.align_ms;
  r.iterations = estimate.iterations;
  r.point_iterations = estimate.point_iterations;
  r.score = estimate.score;
  r.converged = estimate.converged;
  return r;
}

}  // namespace mlndt
