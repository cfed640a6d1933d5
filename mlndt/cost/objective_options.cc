#include "mlndt/cost/objective_options.h"

#include "mlndt/common/internal/check_option.h"

namespace mlndt {

bool ObjectiveOptions::IsValid(std::string* error) const {
  MLNDT_OPTION_ENUM(unmatched_policy, UnmatchedPolicyToString);
  MLNDT_OPTION_ENUM(loss, LossTypeToString);
  MLNDT_OPTION_IN_RANGE(loss_scale, 1e-3, 1e3);
  return true;
}

ObjectiveOptions PaperObjectiveOptions() {
  ObjectiveOptions options;
  options.unmatched_policy = UnmatchedPolicy::ZERO_RESIDUAL;
  options.loss = LossType::NONE;
  options.loss_scale = 3.0;  // Unused without a loss; the earlier default.
  return options;
}

}  // namespace mlndt
