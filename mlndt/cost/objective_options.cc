#include "mlndt/cost/objective_options.h"

#include "mlndt/common/internal/check_option.h"
#include "mlndt/common/option_table.h"

namespace mlndt {

const OptionTable& ObjectiveOptionsTable() {
  using S = ObjectiveOptions;
  static const OptionTable table =
      OptionTableBuilder<S>("ObjectiveOptions")
          .Enum("unmatched_policy",
                &S::unmatched_policy,
                UnmatchedPolicyTable(),
                "What a point in no occupied cell contributes (cell_match.h).")
          .Enum("loss",
                &S::loss,
                LossTypeTable(),
                "Robust loss rho on the per-point score (none: the paper's "
                "plain sum, Eq. 10).")
          .Double("loss_scale",
                  &S::loss_scale,
                  "",
                  Closed(1e-3, 1e3),
                  "Mahalanobis distance sqrt(s) where the robust loss bends.")
          .Validator(&S::IsValid)
          .Build();
  return table;
}

bool ObjectiveOptions::IsValid(std::string* error) const {
  return ObjectiveOptionsTable().Check(*this, error);
}

ObjectiveOptions PaperObjectiveOptions() {
  ObjectiveOptions options;
  options.unmatched_policy = UnmatchedPolicy::ZERO_RESIDUAL;
  options.loss = LossType::NONE;
  options.loss_scale = 3.0;  // Unused without a loss; the earlier default.
  return options;
}

}  // namespace mlndt
