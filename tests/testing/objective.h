#pragma once

// An ObjectiveOptions from its three fields, for tests that sweep them.

#include "mlndt/cost/objective_options.h"

namespace mlndt {
namespace testing {

inline ObjectiveOptions Objective(UnmatchedPolicy policy,
                                  LossType loss = LossType::NONE,
                                  double loss_scale = 1.0) {
  ObjectiveOptions objective;
  objective.unmatched_policy = policy;
  objective.loss = loss;
  objective.loss_scale = loss_scale;
  return objective;
}

}  // namespace testing
}  // namespace mlndt
