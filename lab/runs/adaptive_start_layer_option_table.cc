#include "lab/runs/adaptive_start_layer_option_table.h"

#include <limits>

#include "lab/runs/adaptive_start_layer.h"

namespace mlndt {

const OptionTable& AdaptiveStartLayerOptionsTable() {
  using S = AdaptiveStartLayerOptions;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  static const OptionTable table =
      OptionTableBuilder<S>("AdaptiveStartLayerOptions")
          .Bool("enabled",
                &S::enabled,
                "The paper's adaptive start layer (end of Section 5.3): the "
                "last layer, coarser as the fail rate grows.")
          .Double("max_translation_m",
                  &S::max_translation_m,
                  "m",
                  LeftOpen(0.0, kInf),
                  "A deviation of the estimate from its guess above this is "
                  "a failure...")
          .Double("max_rotation_deg",
                  &S::max_rotation_deg,
                  "deg",
                  LeftOpen(0.0, kInf),
                  "... or above this rotation angle.")
          .DoubleList("fail_rate_thresholds",
                      &S::fail_rate_thresholds,
                      "",
                      Closed(0.0, 1.0),
                      "Ascending running fail rates: above the k-th the "
                      "start is k layers coarser than the last.")
          .Validator(&S::IsValid)
          .Build();
  return table;
}

}  // namespace mlndt
