#include "mlndt/cost/pair_residual_option_table.h"

#include "mlndt/cost/add_pair_residuals.h"

namespace mlndt {

const OptionTable& PairResidualOptionsTable() {
  using S = PairResidualOptions;
  static const OptionTable table =
      OptionTableBuilder<S>("PairResidualOptions")
          .Struct("objective",
                  &S::objective,
                  ObjectiveOptionsTable(),
                  "The unmatched-point policy and robust loss.")
          .Bool("one_block_per_pair",
                &S::one_block_per_pair,
                "One residual block for all points of the pair (the same "
                "normal equations, far less memory and time) instead of one "
                "per point.")
          .Bool("analytic_jacobians",
                &S::analytic_jacobians,
                "Per-point blocks: hand-written Jacobians instead of "
                "auto-diff of the same residual.")
          .Double("information_scale",
                  &S::information_scale,
                  "",
                  LeftOpen(0.0, 1e3),
                  "w: every point's term rho(s) becomes w rho(s), so the "
                  "pair's information is w J^T J; 1 = every sampled point an "
                  "independent measurement (the paper's objective).")
          .Validator(&S::IsValid)
          .Build();
  return table;
}

}  // namespace mlndt
