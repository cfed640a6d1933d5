#pragma once

// Newton's method on the ML-NDT score, the paper's optimiser (Section 4.1,
// Eqs. 12-17): the full Hessian of Eq. (14) including the second-order term
// of the Euler-angle transform, the update xi <- xi - H^-1 g (Eq. 15), and H
// replaced by H + gamma I when it is not safely positive definite. A
// backtracking line search (halving the step until the score decreases) is on
// by default: with cells changing under the points the full Newton step can
// overshoot; without it the step is always taken, as in the paper.

#include <string>

#include "mlndt/solvers/backend.h"
#include "mlndt/solvers/hand_written_backend.h"
#include "mlndt/solvers/objective.h"

namespace mlndt {

class OptionTable;

struct NewtonOptions {
  bool line_search = true;
  // Halvings before the step is rejected. In [1, 60].
  int max_line_search_steps = 8;
  // H counts as safely positive definite when its smallest eigenvalue is at
  // least this fraction of its largest; otherwise gamma lifts it there.
  // In [1e-15, 1].
  double min_eigenvalue_ratio = 1e-6;

  bool IsValid(std::string* error) const;
};

// NewtonOptions's fields: name, unit, valid range and help (option_table.h).
const OptionTable& NewtonOptionsTable();

// Minimises `objective` from *xi for at most control.max_iterations
// iterations, recording one IterationRecord per iteration.
void MinimizeNewton(const Objective& objective,
                    const NewtonOptions& newton_options,
                    const StageControl& control,
                    Vector6d* reference_from_input_xi,
                    StageSummary* summary);

// The hand-written shell (hand_written_backend.h) around MinimizeNewton.
class NewtonBackend : public HandWrittenBackend {
 public:
  explicit NewtonBackend(const NewtonOptions& options)
      : HandWrittenBackend("NewtonBackend"), options_(options) {}

 private:
  void Minimize(const Objective& objective,
                const StageControl& control,
                Vector6d* reference_from_input_xi,
                StageSummary* summary) const override;

  NewtonOptions options_;
};

}  // namespace mlndt
