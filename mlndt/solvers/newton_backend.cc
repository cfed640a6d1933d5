#include "mlndt/solvers/newton_backend.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "mlndt/common/check_option.h"
#include "mlndt/solvers/trace_recorder.h"

namespace mlndt {
namespace {

// H + gamma I with gamma chosen so that the smallest eigenvalue is at least
// `ratio` times the largest (Section 4.1, "safely positive definite").
Matrix6d SafelyPositiveDefinite(const Matrix6d& h, double ratio) {
  const Eigen::SelfAdjointEigenSolver<Matrix6d> solver(h,
                                                       Eigen::EigenvaluesOnly);
  const double largest =
      std::max(std::abs(solver.eigenvalues().maxCoeff()), 1e-12);
  const double smallest = solver.eigenvalues().minCoeff();
  const double gamma = std::max(0.0, ratio * largest - smallest);
  return h + gamma * Matrix6d::Identity();
}

}  // namespace

bool NewtonOptions::IsValid(std::string* error) const {
  MLNDT_OPTION_GE(max_line_search_steps, 1);
  MLNDT_OPTION_GT(min_eigenvalue_ratio, 0.0);
  return true;
}

void MinimizeNewton(const Objective& objective,
                    const NewtonOptions& newton_options,
                    const StageOptions& options,
                    Vector6d* xi,
                    StageSummary* summary) {
  *summary = StageSummary();
  TraceRecorder trace(options, summary);
  summary->termination_type = TerminationType::NO_CONVERGENCE;
  summary->message = "iteration cap reached";
  for (int iteration = 0; iteration < options.max_iterations; ++iteration) {
    const ScoreEvaluation current = objective.Evaluate(*xi, HessianType::FULL);
    summary->final_score = current.score;
    if (current.matched == 0) {
      summary->termination_type = TerminationType::FAILURE;
      summary->message = "no input point lies in an occupied cell";
      return;
    }
    // Eq. (15): xi <- xi - H^-1 g.
    const Matrix6d h = SafelyPositiveDefinite(
        current.hessian, newton_options.min_eigenvalue_ratio);
    const Vector6d step = -h.ldlt().solve(current.gradient);
    if (!step.allFinite()) {
      summary->termination_type = TerminationType::FAILURE;
      summary->message = "the Newton step is not finite";
      return;
    }
    double scale = 1.0;
    Vector6d candidate = *xi + step;
    double candidate_score = current.score;
    bool successful = true;
    if (newton_options.line_search) {
      successful = false;
      for (int k = 0; k < newton_options.max_line_search_steps;
           ++k, scale *= 0.5) {
        candidate = *xi + scale * step;
        candidate_score =
            objective.Evaluate(candidate, HessianType::NONE).score;
        if (candidate_score < current.score) {
          successful = true;
          break;
        }
      }
    }
    if (successful) {
      *xi = candidate;
      summary->final_score = candidate_score;
    }
    const double step_norm = scale * step.norm();
    const bool converged =
        trace.Record(summary->final_score, step_norm, successful, *xi);
    if (converged) {
      summary->termination_type = TerminationType::CONVERGENCE;
      summary->message = "update norm below tolerance";
      return;
    }
    if (!successful) {
      // No decrease along the Newton direction: a (local) minimum.
      summary->termination_type = TerminationType::CONVERGENCE;
      summary->message = "no decrease along the Newton direction";
      return;
    }
  }
}

void NewtonBackend::SolveStage(const NdtLayer& layer,
                               const std::vector<Eigen::Vector3d>& input_points,
                               const StageOptions& options,
                               Vector6d* reference_from_input_xi,
                               StageSummary* summary) {
  std::vector<Eigen::Vector3d> thinned;
  const auto& points =
      internal::EveryNthPoint(input_points, options.point_stride, &thinned);
  MinimizeNewton(MlNdtObjective(layer, points, ScoreOptionsForStage(options)),
                 options_,
                 options,
                 reference_from_input_xi,
                 summary);
}

}  // namespace mlndt
