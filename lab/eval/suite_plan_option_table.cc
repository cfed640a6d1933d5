#include "lab/eval/suite_plan_option_table.h"

#include "lab/eval/suite_plan.h"

namespace mlndt {

const OptionTable& SuitePlanOptionsTable() {
  using S = SuitePlanOptions;
  static const OptionTable table =
      OptionTableBuilder<S>("SuitePlanOptions")
          .Double("perturb_translation_m",
                  &S::perturb_translation_m,
                  "m",
                  Closed(0.0, 1e4),
                  "Perturbed starts: bound of the random translation offset.")
          .Double("perturb_rotation_deg",
                  &S::perturb_rotation_deg,
                  "deg",
                  Closed(0.0, 180.0),
                  "Perturbed starts: bound of the random rotation offset.")
          .Int("perturb_count",
               &S::perturb_count,
               AtLeast(1),
               "Perturbed starts: random starts per pair.")
          .Uint64("perturb_seed",
                  &S::perturb_seed,
                  "Perturbed starts: seed of the random offsets.")
          .Uint64("max_pairs_per_set",
                  &S::max_pairs_per_set,
                  "At most this many pairs per data set, smallest steps "
                  "first; 0 = all.")
          .Validator(&S::IsValid)
          .Build();
  return table;
}

}  // namespace mlndt
