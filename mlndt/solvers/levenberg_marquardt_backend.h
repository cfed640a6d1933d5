#pragma once

// Levenberg-Marquardt on the whitened residuals r_k = W_k e_k (Section 4.2).
// The paper writes the per-point score s_k itself as the residual
// (Eqs. 18-20); by default we use the 3-vector W_k e_k, whose squared norm
// is s_k, so the objective sum_k s_k is the same as Newton's and Ceres', and
// J^T J is the Gauss-Newton Hessian of that sum (README: "Choosing a
// solver"). LmResidual::SCALAR_SCORE runs the paper's literal form instead
// (cost/scalar_residual.h), for reproducing its Newton-vs-LM comparison.
// The damping follows the paper: lambda starts at 1e-3 times the mean of
// diag(J^T J), is divided by 10 after a step that lowers the score and
// multiplied by 10 (the step rejected) otherwise.

#include <string>

#include "mlndt/solvers/backend.h"
#include "mlndt/solvers/hand_written_backend.h"
#include "mlndt/solvers/objective.h"

namespace mlndt {

class EnumTable;
class OptionTable;

// What the LM normal equations are built from.
enum class LmResidual {
  // Whitened 3-vectors W_k e_k: the normal equations of the score itself.
  WHITENED,
  // The paper's literal residual s_k per point (Eqs. 18-20,
  // cost/scalar_residual.h): the normal equations of (1/2) sum_k s_k^2.
  // For reproducing the paper's Newton-vs-LM comparison only.
  SCALAR_SCORE,
};

// "WHITENED", "SCALAR_SCORE".
// The names of LmResidual's values (enum_table.h).
const EnumTable& LmResidualTable();
const char* LmResidualToString(LmResidual residual);
// Case-insensitive.
bool StringToLmResidual(std::string value, LmResidual* residual);

struct LevenbergMarquardtOptions {
  // lambda_0 / mean(diag(J^T J)). In [1e-15, 1e6].
  double initial_lambda_factor = 1e-3;
  double lambda_decrease = 10.0;  // After a successful step. In (1, 1e6].
  double lambda_increase = 10.0;  // After a rejected step. In (1, 1e6].
  LmResidual residual = LmResidual::WHITENED;

  bool IsValid(std::string* error) const;
};

// LevenbergMarquardtOptions's fields: name, unit, valid range and help
// (option_table.h).
const OptionTable& LevenbergMarquardtOptionsTable();

void MinimizeLevenbergMarquardt(const Objective& objective,
                                const LevenbergMarquardtOptions& lm_options,
                                const StageControl& control,
                                Vector6d* reference_from_input_xi,
                                StageSummary* summary);

// The hand-written shell (hand_written_backend.h) around
// MinimizeLevenbergMarquardt.
class LevenbergMarquardtBackend : public HandWrittenBackend {
 public:
  explicit LevenbergMarquardtBackend(const LevenbergMarquardtOptions& options)
      : HandWrittenBackend("LevenbergMarquardtBackend"), options_(options) {}

 private:
  void Minimize(const Objective& objective,
                const StageControl& control,
                Vector6d* reference_from_input_xi,
                StageSummary* summary) const override;

  LevenbergMarquardtOptions options_;
};

}  // namespace mlndt
