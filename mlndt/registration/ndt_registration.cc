#include "mlndt/registration/ndt_registration.h"

#include <glog/logging.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>

#include "mlndt/common/pose.h"
#include "mlndt/common/timer.h"
#include "mlndt/grid/single_grid.h"
#include "mlndt/registration/ndt_objective.h"
#include "mlndt/solvers/newton_backend.h"

namespace mlndt {
namespace internal {
namespace {

GaussianScoreOptions ScoreOptionsFor(const RegistrationOptions& options) {
  GaussianScoreOptions score;
  score.outlier_ratio = options.ndt.outlier_ratio;
  score.neighbors = options.ndt.neighbors;
  score.num_threads = options.num_threads;
  return score;
}

// H^-1 when H is positive definite, else zero. The Gaussian score
// approximates the negative log-likelihood of the input points up to a
// constant (Magnusson Eq. 6.8), so H^-1 is its Laplace covariance.
Matrix6d CovarianceFromHessian(const Matrix6d& hessian) {
  const Eigen::LLT<Matrix6d> llt(hessian);
  if (llt.info() != Eigen::Success) return Matrix6d::Zero();
  const Matrix6d covariance = llt.solve(Matrix6d::Identity());
  return covariance.allFinite() ? covariance : Matrix6d::Zero();
}

// The objective with its Newton Hessian shifted to H + mu I, mu >= 0, so
// that the Newton step -(H + mu I)^-1 g is no longer than `max_step_norm`:
// the solution of the trust-region subproblem min g^T p + p^T H p / 2 s.t.
// ||p|| <= max_step_norm (Nocedal & Wright, Theorem 4.1). Away from the
// minimum the Gaussian score's Hessian is indefinite; lifted by a tiny
// multiple of I, its Newton step runs hundreds of metres along the negative
// curvature. PCL's NDT bounds its step for the same reason (step_size).
class StepBoundedObjective : public Objective {
 public:
  StepBoundedObjective(const Objective& objective, double max_step_norm)
      : objective_(objective), max_step_norm_(max_step_norm) {}

  ScoreEvaluation Evaluate(const Vector6d& xi,
                           HessianType hessian) const override {
    ScoreEvaluation evaluation = objective_.Evaluate(xi, hessian);
    if (hessian == HessianType::FULL && max_step_norm_ > 0.0) {
      evaluation.hessian.diagonal().array() +=
          Shift(evaluation.hessian, evaluation.gradient);
    }
    return evaluation;
  }

 private:
  // The smallest mu >= 0 with H + mu I positive definite and
  // ||(H + mu I)^-1 g|| <= max_step_norm, by bisection on the eigenbasis.
  double Shift(const Matrix6d& h, const Vector6d& g) const {
    const Eigen::SelfAdjointEigenSolver<Matrix6d> solver(h);
    const Vector6d lambda = solver.eigenvalues();
    const Vector6d gv = solver.eigenvectors().transpose() * g;
    const double scale = std::max(lambda.cwiseAbs().maxCoeff(), 1e-12);
    const auto step_norm = [&](double mu) {
      return (gv.array() / (lambda.array() + mu)).matrix().norm();
    };
    // Positive definite with a margin, as MinimizeNewton requires.
    double low = std::max(0.0, -lambda.minCoeff() + 1e-6 * scale);
    if (step_norm(low) <= max_step_norm_) return low;
    double high = low + std::max(scale, g.norm() / max_step_norm_);
    while (step_norm(high) > max_step_norm_) high *= 2.0;
    for (int i = 0; i < 60; ++i) {
      const double mid = 0.5 * (low + high);
      if (step_norm(mid) > max_step_norm_) {
        low = mid;
      } else {
        high = mid;
      }
    }
    return high;  // ||step|| <= max_step_norm.
  }

  const Objective& objective_;
  const double max_step_norm_;
};

}  // namespace

bool BuildNdtGrid(const RegistrationOptions& options,
                  const PointCloud& reference,
                  NdtLayer* grid,
                  std::string* error) {
  SingleGridOptions grid_options;
  grid_options.cell_size_m = options.ndt.cell_size_m;
  grid_options.min_points_per_cell = options.grid.min_points_per_cell;
  grid_options.regularization = options.grid.regularization;
  LayerInfo info;
  return BuildSingleGrid(grid_options, reference, grid, &info, error);
}

bool RegisterOnNdtGrid(const RegistrationOptions& options,
                       const NdtLayer& grid,
                       const std::vector<Eigen::Vector3d>& sampled_points,
                       const Vector6d& initial_xi,
                       double start_time_s,
                       RegistrationSummary* summary,
                       std::string* error) {
  CHECK(summary != nullptr);
  CHECK(error != nullptr);
  const NdtGaussianObjective objective(
      grid, sampled_points, ScoreOptionsFor(options));
  summary->ndt_cell_size_m = grid.cell_size();
  summary->initial_reference_from_input_xi = initial_xi;
  summary->num_layers = 1;
  summary->start_layer = 1;
  summary->initial_score =
      objective.Evaluate(initial_xi, HessianType::NONE).score;

  StageOptions stage;
  stage.layer = 1;
  stage.max_iterations = options.ndt.max_iterations;
  stage.step_tolerance = options.schedule.step_tolerance;
  stage.num_threads = options.num_threads;
  stage.start_time_s = start_time_s;
  stage.first_iteration = 1;
  Vector6d xi = initial_xi;
  StageSummary newton;
  const double t0 = NowSeconds();
  const StepBoundedObjective bounded(objective, options.ndt.max_step_norm);
  MinimizeNewton(bounded, options.newton, stage, &xi, &newton);
  summary->solve_time_s = NowSeconds() - t0;
  summary->trace = newton.trace;
  summary->iterations_per_layer = {newton.iterations};
  summary->num_iterations = newton.iterations;
  if (newton.termination_type == TerminationType::FAILURE) {
    *error = newton.message;
    return false;
  }
  if (!xi.allFinite()) {
    *error = "the solver returned a non-finite pose";
    return false;
  }

  // Results at the solution, with the full Newton Hessian (Eq. 6.13).
  const ScoreEvaluation final = objective.Evaluate(xi, HessianType::FULL);
  summary->reference_from_input_xi = xi;
  summary->reference_from_input = PoseVectorToIsometry(xi);
  summary->final_score = final.score;
  summary->matched_points = final.matched;
  summary->unmatched_points = final.unmatched;
  summary->hessian = final.hessian;
  summary->covariance = CovarianceFromHessian(final.hessian);
  summary->termination_type = newton.termination_type;
  summary->message = newton.message;
  return true;
}

}  // namespace internal
}  // namespace mlndt
