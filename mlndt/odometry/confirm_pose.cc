#include "mlndt/odometry/confirm_pose.h"

#include <sstream>

#include "mlndt/common/internal/check_option.h"
#include "mlndt/common/pose.h"
#include "mlndt/registration/registration.h"
#include "mlndt/registration/rival_minima.h"

namespace mlndt {

bool ConfirmationOptions::IsValid(std::string* error) const {
  MLNDT_OPTION_GE(min_correction_fraction, 0.0);
  return true;
}

bool NeedsConfirmation(const ConfirmationOptions& options,
                       const MotionPredictionOptions& prediction,
                       const PredictionUncertainty& uncertainty,
                       const Isometry3d& predicted,
                       const Isometry3d& pose) {
  if (!options.enabled) return false;
  const bool at_maximum =
      uncertainty.translation_m >= prediction.max_translation_m &&
      uncertainty.rotation_deg >= prediction.max_rotation_deg;
  const double fraction = options.min_correction_fraction;
  return at_maximum ||
         TranslationErrorM(predicted, pose) >
             fraction * uncertainty.translation_m ||
         RotationErrorRad(predicted, pose) * kRadToDeg >
             fraction * uncertainty.rotation_deg;
}

Isometry3d ConfirmationStart(const PredictionUncertainty& uncertainty,
                             const Isometry3d& predicted,
                             const Isometry3d& pose) {
  Vector6d twist = MotionToTwist(predicted.inverse() * pose);
  const double t = twist.head<3>().norm();
  const double r = twist.tail<3>().norm();
  const double t_to = uncertainty.translation_m;
  const double r_to = uncertainty.rotation_deg / kRadToDeg;
  if (t > 0.0 && t < t_to) twist.head<3>() *= t_to / t;
  if (r > 0.0 && r < r_to) twist.tail<3>() *= r_to / r;
  return pose * TwistToMotion(twist);
}

namespace {

// The second run returned to the pose when it ended within the
// prediction's smallest uncertainty of it (each bound): a minimum farther
// away is distinct (rival_minima.h) and rivals the pose, whatever its fit.
MinimaSeparation ReturnedWithin(const MotionPredictionOptions& prediction) {
  MinimaSeparation separation;
  separation.cell_size_m = prediction.min_translation_m;
  separation.max_cells = 1.0;
  separation.max_rotation_deg = prediction.min_rotation_deg;
  return separation;
}

}  // namespace

Confirmation ConfirmPose(const MotionPredictionOptions& prediction,
                         const LayeredGrid& map,
                         PreparedRegistration* scan,
                         const PredictionUncertainty& uncertainty,
                         const Isometry3d& predicted,
                         const Isometry3d& pose) {
  Confirmation confirmation;
  confirmation.ran = true;
  RegistrationSummary summary;
  scan->Register(
      map, ConfirmationStart(uncertainty, predicted, pose), &summary);
  confirmation.time_s = summary.total_time_s;
  confirmation.distance_m =
      TranslationErrorM(pose, summary.reference_from_input);
  confirmation.distance_deg =
      RotationErrorRad(pose, summary.reference_from_input) * kRadToDeg;
  const bool returned = !DistinctMinima(
      ReturnedWithin(prediction), pose, summary.reference_from_input);
  // The question is where the second run ends, not its own verdict (the
  // first run's quality check already passed at the pose): only a FAILURE
  // has no pose to compare.
  const bool failed = summary.termination_type == TerminationType::FAILURE;
  confirmation.confirmed = !failed && returned;
  confirmation.agreed = confirmation.confirmed;
  if (!confirmation.confirmed) {
    std::ostringstream message;
    message.precision(3);
    message << "not confirmed: from beyond the pose the registration ";
    if (failed) {
      message << "failed (" << summary.message << ")";
    } else {
      message << "stopped " << confirmation.distance_m << " m, "
              << confirmation.distance_deg << " deg from it (more than "
              << prediction.min_translation_m << " m or "
              << prediction.min_rotation_deg << " deg)";
    }
    confirmation.message = message.str();
  }
  return confirmation;
}

}  // namespace mlndt
