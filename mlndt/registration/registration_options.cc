#include "mlndt/registration/registration_options.h"

#include "mlndt/common/internal/check_option.h"

namespace mlndt {

bool InitialGuessUncertainty::IsValid(std::string* error) const {
  MLNDT_OPTION_IN_RANGE(translation_m, 0.0, 1e4);
  MLNDT_OPTION_IN_RANGE(rotation_deg, 0.0, 180.0);
  return true;
}

bool RetryOptions::IsValid(std::string* error) const {
  MLNDT_OPTION_LE(yaw_seeds_deg.size(), size_t{36});
  for (const double yaw_deg : yaw_seeds_deg) {
    MLNDT_OPTION_IN_RANGE(yaw_deg, -180.0, 180.0);
  }
  return true;
}

bool RegistrationOptions::IsValid(std::string* error) const {
  if (!quality_check.IsValid(error) || !initial_uncertainty.IsValid(error) ||
      !retry.IsValid(error) || !range_filter.IsValid(error) ||
      !grid.IsValid(error) || !sampling.IsValid(error) ||
      !schedule.IsValid(error) || !objective.IsValid(error) ||
      !backend.IsValid(error)) {
    return false;
  }
  MLNDT_OPTION_IN_RANGE(num_threads, 1, 256);
  MLNDT_OPTION_IN_RANGE(min_matched_fraction, 0.0, 1.0);
  return true;
}

RegistrationOptions PaperRegistrationOptions() {
  RegistrationOptions options;
  options.grid = PaperLayeredGridOptions();
  options.schedule = PaperLayerScheduleOptions();
  options.objective = PaperObjectiveOptions();
  options.backend.type = BackendType::NEWTON;
  options.retry.yaw_seeds_deg.clear();
  return options;
}

}  // namespace mlndt
