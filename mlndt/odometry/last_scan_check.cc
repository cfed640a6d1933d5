#include "mlndt/odometry/last_scan_check.h"

#include <sstream>

#include "mlndt/common/pose.h"
#include "mlndt/registration/registration.h"

namespace mlndt {

Confirmation CheckAgainstLastScan(const MotionPredictionOptions& prediction,
                                  const LayeredGrid& last_scan_map,
                                  PreparedRegistration* scan,
                                  const Isometry3d& predicted,
                                  const Isometry3d& pose) {
  Confirmation check;
  check.ran = true;
  RegistrationSummary summary;
  scan->Register(last_scan_map, predicted, &summary);
  check.time_s = summary.total_time_s;
  if (!summary.IsSolutionUsable()) return check;  // No evidence.
  check.distance_m = TranslationErrorM(pose, summary.reference_from_input);
  check.distance_deg =
      RotationErrorRad(pose, summary.reference_from_input) * kRadToDeg;
  check.confirmed = check.distance_m <= prediction.min_translation_m &&
                    check.distance_deg <= prediction.min_rotation_deg;
  check.agreed = check.confirmed;
  if (!check.confirmed) {
    std::ostringstream message;
    message.precision(3);
    message << "not confirmed: registered onto the last registered scan "
            << "alone it ends " << check.distance_m << " m, "
            << check.distance_deg << " deg from the pose (more than "
            << prediction.min_translation_m << " m or "
            << prediction.min_rotation_deg << " deg)";
    check.message = message.str();
  }
  return check;
}

}  // namespace mlndt
