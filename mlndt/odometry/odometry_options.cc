#include "mlndt/odometry/odometry_options.h"

#include "mlndt/odometry/odometry_option_tables.h"

namespace mlndt {

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
