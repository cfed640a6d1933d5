#include "mlndt/odometry/odometry_options.h"

#include "mlndt/common/internal/check_option.h"

namespace mlndt {

bool OdometryOptions::IsValid(std::string* error) const {
  if (!registration.IsValid(error) || !local_map.IsValid(error) ||
      !keyframes.IsValid(error) || !prediction.IsValid(error) ||
      !confirmation.IsValid(error)) {
    return false;
  }
  MLNDT_OPTION_GE(gate_factor, 1.0);
  MLNDT_OPTION_GE(max_consecutive_fallbacks, 1);
  MLNDT_OPTION_GT(max_flatness, 0.0);
  MLNDT_OPTION_LE(max_flatness, 1.0);
  MLNDT_OPTION_IN_RANGE(weak_direction_rounds, 0, 16);
  MLNDT_OPTION_GT(max_mean_score, 0.0);
  MLNDT_OPTION_LE(max_mean_score, 1e6);
  return true;
}

}  // namespace mlndt
