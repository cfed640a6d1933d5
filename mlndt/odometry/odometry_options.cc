#include "mlndt/odometry/odometry_options.h"

#include "mlndt/odometry/odometry_option_tables.h"

namespace mlndt {

RegistrationOptions OdometryRegistrationOptions() {
  RegistrationOptions options;
  options.quality_check.max_flatness = 0.8;
  options.retry.weak_direction_rounds = 0;
  options.quality_check.max_mean_score = 11.0;
  options.quality_check.min_localizability = 0.0;
  return options;
}

bool OdometryOptions::IsValid(std::string* error) const {
  // The nested structs by their own IsValid, then the own fields' ranges
  // (OdometryOwnOptionsTable; its CheckRanges leaves the nested structs to
  // those).
  return registration.IsValid(error) && local_map.IsValid(error) &&
         keyframes.IsValid(error) && prediction.IsValid(error) &&
         confirmation.IsValid(error) && recovery.IsValid(error) &&
         OdometryOwnOptionsTable().Check(*this, error);
}

}  // namespace mlndt
