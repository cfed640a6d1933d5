#include "lab/runs/sequence_option_table.h"

#include "lab/runs/sequence_registration.h"

namespace mlndt {

const OptionTable& SequenceOwnOptionsTable() {
  using S = SequenceOptions;
  static const OptionTable table =
      OptionTableBuilder<S>("SequenceOptions")
          .Uint64("step",
                  &S::step,
                  AtLeast(1),
                  "Register scan i + step onto scan i.")
          .Validator(&S::IsValid)
          .Build();
  return table;
}

}  // namespace mlndt
