#include "mlndt/odometry/keyframe_policy.h"

#include "mlndt/common/internal/check_option.h"
#include "mlndt/common/pose.h"

namespace mlndt {

bool KeyframeOptions::IsValid(std::string* error) const {
  MLNDT_OPTION_GT(min_translation_m, 0.0);
  MLNDT_OPTION_GT(min_rotation_deg, 0.0);
  return true;
}

bool IsNewKeyframe(const KeyframeOptions& options,
                   const Isometry3d& last_keyframe,
                   const Isometry3d& world_from_sensor) {
  return TranslationErrorM(last_keyframe, world_from_sensor) >=
             options.min_translation_m ||
         RotationErrorRad(last_keyframe, world_from_sensor) * kRadToDeg >=
             options.min_rotation_deg;
}

}  // namespace mlndt
