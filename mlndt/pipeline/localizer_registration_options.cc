#include "mlndt/pipeline/localizer.h"

namespace mlndt {

RegistrationOptions LocalizerRegistrationOptions() {
  RegistrationOptions options;
  options.quality_check.min_localizability = 0.0;
  return options;
}

}  // namespace mlndt
