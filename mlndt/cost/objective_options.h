#pragma once

// The ML-NDT objective, as one value: what every backend, the analytic score
// (score.h) and the embedding API (add_residuals.h) minimise,
//
//   sum_k rho(s_k),   s_k = e_k^T C_k^-1 e_k                    (Eq. 10)
//
// over the sampled input points k, with the cell of each point chosen by the
// unmatched-point policy (cell_match.h) and rho a robust loss
// (robust_loss.h). RegistrationOptions holds it once and passes it unchanged
// to every component. The defaults are the library's (docs/defaults.md says
// why); PaperObjectiveOptions() is the paper's plain sum over own cells.

#include <string>

#include "mlndt/cost/cell_match.h"
#include "mlndt/cost/robust_loss.h"

namespace mlndt {

class OptionTable;

struct ObjectiveOptions {
  // What a point in no occupied cell contributes (cell_match.h).
  UnmatchedPolicy unmatched_policy = UnmatchedPolicy::NEAREST_CELL;
  // rho; NONE is the paper's plain sum.
  LossType loss = LossType::CAUCHY;
  // Mahalanobis distance sqrt(s) where the loss bends. In [1e-3, 1e3].
  double loss_scale = 1.5;

  bool IsValid(std::string* error) const;
};

// ObjectiveOptions's fields: name, unit, valid range and help (option_table.h).
const OptionTable& ObjectiveOptionsTable();

// The paper's objective: own cells only (ZERO_RESIDUAL), no loss.
ObjectiveOptions PaperObjectiveOptions();

}  // namespace mlndt
