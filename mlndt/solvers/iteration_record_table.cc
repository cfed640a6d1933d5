#include "mlndt/common/result_table.h"
#include "mlndt/solvers/backend.h"

namespace mlndt {

const ResultTable& IterationRecordTable() {
  using R = IterationRecord;
  static const ResultTable table =
      ResultTableBuilder<R>("IterationRecord")
          .Integer(
              "layer", &R::layer, "", "1-based layer the iteration ran on.")
          .Integer("iteration",
                   &R::iteration,
                   "",
                   "Count over the whole registration, from 1.")
          .Number("score",
                  &R::score,
                  "",
                  "The objective after the iteration, on its layer.")
          .Number("step_norm",
                  &R::step_norm,
                  "m, rad",
                  "||delta xi|| of the step tried (metres and radians "
                  "together, as the solver sees it).")
          .Bool("step_is_successful",
                &R::step_is_successful,
                "Whether the step was taken.")
          .Vector("reference_from_input_xi",
                  &R::reference_from_input_xi,
                  "m, rad",
                  "The pose vector (tx, ty, tz, alpha, beta, gamma) after the "
                  "iteration (Eq. 11).")
          .Number("time_s",
                  &R::time_s,
                  "s",
                  "Wall time from the registration's start.")
          .Build();
  return table;
}

}  // namespace mlndt
