#pragma once

// The error of an estimated pose against the truth, the success criteria the
// reports count with, and scaling a motion (the paper's initialisation
// Z_i = c Z_gt, Table 9).

#include <limits>

#include "mlndt/common/pose.h"
#include "mlndt/common/types.h"

namespace mlndt {

// Error of an estimated transform (e.g. reference_from_input) against the
// truth. The error transform is E = truth^-1 * estimate, which maps the frame
// as estimated into the frame as it truly is; `components` is its pose vector
// (IsometryToPoseVector: tx, ty, tz [m], alpha, beta, gamma [rad]).
// translation_m = |t(E)| equals TranslationErrorM(truth, estimate) and
// rotation_rad = angle(R(E)) equals RotationErrorRad(truth, estimate).
struct PoseError {
  Vector6d components = Vector6d::Zero();
  double translation_m = 0.0;
  double rotation_rad = 0.0;

  double rotation_deg() const { return rotation_rad * kRadToDeg; }
};

PoseError ComputePoseError(const Isometry3d& truth, const Isometry3d& estimate);

// A registration succeeds when its error is strictly below both limits. The
// default is the strict rule of the tests and the convergence experiments.
struct SuccessCriterion {
  double max_translation_m = 0.2;  // Success needs translation_m < this.
  double max_rotation_deg = 1.0;   // ... and rotation_deg() < this.

  bool IsWithin(const PoseError& error) const;
};

// The paper's success rule (Section 5.2.1): translation error below 50 cm;
// the rotation is not checked.
constexpr double kPaperSuccessTranslationM = 0.5;
inline constexpr SuccessCriterion kPaperSuccessCriterion{
    kPaperSuccessTranslationM, std::numeric_limits<double>::infinity()};

// Scales a relative motion by c: the translation by c and the rotation's
// axis-angle by c (the paper's initialisation Z_i = c Z_gt, Table 9).
Isometry3d ScaleMotion(const Isometry3d& motion, double c);

}  // namespace mlndt
