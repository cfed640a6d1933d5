#include "mlndt/registration/internal/prior_hold.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "mlndt/common/pose.h"
#include "mlndt/cost/fit_quality.h"
#include "mlndt/cost/score.h"
#include "mlndt/registration/internal/direction_probe.h"

namespace mlndt {
namespace internal {
namespace {

// A direction whose part orthogonal to those before it is shorter than this
// adds nothing new to the free basis.
constexpr double kIndependentNorm = 0.3;

// Gauss-Newton steps over the constrained directions (step 3), at most.
constexpr int kMaxSteps = 10;

// A step shorter than this [m, scaled as the rows] ends them.
constexpr double kStepTolerance = 1e-6;

// Halvings of a step that raises the score before giving up.
constexpr int kMaxHalvings = 8;

// Step 1: the free directions, orthonormalised (Gram-Schmidt); 6 x k.
Eigen::MatrixXd FreeBasis(const std::vector<Vector6d>& directions) {
  std::vector<Vector6d> basis;
  for (const Vector6d& d : directions) {
    Vector6d v = d.normalized();
    for (const Vector6d& b : basis) v -= b.dot(v) * b;
    if (v.norm() >= kIndependentNorm) basis.push_back(v.normalized());
  }
  Eigen::MatrixXd f(6, static_cast<Eigen::Index>(basis.size()));
  for (size_t i = 0; i < basis.size(); ++i) {
    f.col(static_cast<Eigen::Index>(i)) = basis[i];
  }
  return f;
}

// Step 1: an orthonormal basis of the complement of F's columns; 6 x (6-k).
Eigen::MatrixXd ConstrainedBasis(const Eigen::MatrixXd& free) {
  const Matrix6d projector =
      Matrix6d::Identity() - free * free.transpose();  // Onto the rest.
  const Eigen::SelfAdjointEigenSolver<Matrix6d> solver(projector);
  // Eigenvalues ascending: k zeros (F), then 6 - k ones.
  return solver.eigenvectors().rightCols(6 - free.cols());
}

// The pose `xi_local` moved by the scaled left perturbation delta
// (MovedAlong's: rotation omega = delta_r / L about the centroid).
Vector6d Moved(const Vector6d& xi_local, const Vector6d& delta, double lever) {
  return IsometryToPoseVector(
      MovedAlong(PoseVectorToIsometry(xi_local), delta, 1.0, lever));
}

// The scaled left perturbation from pose a to pose b: the translation, and
// the rotation vector of R_b R_a^T times the lever.
Vector6d Delta(const Vector6d& a, const Vector6d& b, double lever) {
  const Isometry3d pa = PoseVectorToIsometry(a), pb = PoseVectorToIsometry(b);
  const Eigen::AngleAxisd turn(pb.linear() * pa.linear().transpose());
  Vector6d d;
  d << pb.translation() - pa.translation(), turn.angle() * lever * turn.axis();
  return d;
}

// J = d xi / d delta at `xi_local` (central differences; the angles'
// differences wrapped).
Matrix6d PerturbationJacobian(const Vector6d& xi_local, double lever) {
  constexpr double h = 1e-6;
  Matrix6d j;
  for (int i = 0; i < 6; ++i) {
    const Vector6d e = Vector6d::Unit(i) * h;
    Vector6d diff = Moved(xi_local, e, lever) - Moved(xi_local, -e, lever);
    for (int a = 3; a < 6; ++a) diff(a) = std::remainder(diff(a), 2.0 * M_PI);
    j.col(i) = diff / (2.0 * h);
  }
  return j;
}

struct LastLayerScore {
  const Problem& problem;
  const ObjectiveOptions& options;
  ScoreEvaluation At(const Vector6d& xi_local,
                     HessianType hessian = HessianType::GAUSS_NEWTON) const {
    return EvaluateScore(
        problem.last(), problem.points, xi_local, options, hessian);
  }
};

// Step 3: Gauss-Newton over V's span from *xi_local, each step halved until
// the score does not rise. Returns the evaluation at the end.
ScoreEvaluation MinimiseOver(const LastLayerScore& objective,
                             const Eigen::MatrixXd& v,
                             double lever,
                             Vector6d* xi_local) {
  ScoreEvaluation at = objective.At(*xi_local);
  for (int step = 0; step < kMaxSteps; ++step) {
    const Matrix6d j = PerturbationJacobian(*xi_local, lever);
    const Eigen::MatrixXd reduced =
        v.transpose() * j.transpose() * at.hessian * j * v;  // V^T H_delta V.
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(reduced);
    if (ldlt.info() != Eigen::Success || !ldlt.isPositive()) break;
    Vector6d delta =
        -v * ldlt.solve(v.transpose() * j.transpose() * at.gradient);
    bool improved = false;
    for (int halving = 0; halving <= kMaxHalvings; ++halving, delta *= 0.5) {
      const Vector6d trial = Moved(*xi_local, delta, lever);
      const ScoreEvaluation there = objective.At(trial);
      if (there.score <= at.score) {
        *xi_local = trial;
        at = there;
        improved = true;
        break;
      }
    }
    if (!improved || delta.norm() < kStepTolerance) break;
  }
  return at;
}

// Step 4: the covariance of xi_local, the Laplace one on V, the prior's on
// F; non-finite when V^T H V is not positive definite.
Matrix6d HeldCovariance(const InitialGuessUncertainty& prior,
                        const Eigen::MatrixXd& free,
                        const Eigen::MatrixXd& v,
                        const Matrix6d& hessian,
                        const Vector6d& xi_local,
                        double lever) {
  const Matrix6d j = PerturbationJacobian(xi_local, lever);
  const Eigen::MatrixXd reduced =
      v.transpose() * j.transpose() * hessian * j * v;
  const Eigen::LLT<Eigen::MatrixXd> llt(reduced);
  if (llt.info() != Eigen::Success) {
    return Matrix6d::Constant(std::numeric_limits<double>::infinity());
  }
  Vector6d p;  // diag(P): the prior in delta's units.
  const double s_r = prior.rotation_deg * kDegToRad * lever;
  p << Eigen::Vector3d::Constant(prior.translation_m * prior.translation_m),
      Eigen::Vector3d::Constant(s_r * s_r);
  const Eigen::MatrixXd identity =
      Eigen::MatrixXd::Identity(reduced.rows(), reduced.cols());
  const Matrix6d c_delta =
      v * (2.0 * llt.solve(identity)) * v.transpose() +
      free * (free.transpose() * p.asDiagonal() * free) * free.transpose();
  return j * c_delta * j.transpose();
}

}  // namespace

int HoldPriorAlongFreeDirections(const RegistrationOptions& options,
                                 const Problem& problem,
                                 const Vector6d& initial_local,
                                 Attempt* attempt) {
  if (!options.initial_uncertainty.given ||
      attempt->schedule.termination_type == TerminationType::FAILURE ||
      attempt->constraints.degenerate_directions.empty()) {
    return 0;
  }
  const double lever = std::max(problem.rms_range_m, 1e-3);
  const Eigen::MatrixXd free =
      FreeBasis(attempt->constraints.degenerate_directions);
  const Eigen::MatrixXd v = ConstrainedBasis(free);
  // Step 2: the update without its free part.
  const Vector6d update = Delta(initial_local, attempt->xi_local, lever);
  Vector6d xi =
      Moved(initial_local, update - free * (free.transpose() * update), lever);
  const LastLayerScore objective{problem, options.objective};
  attempt->evaluation =
      v.cols() > 0 ? MinimiseOver(objective, v, lever, &xi) : objective.At(xi);
  attempt->xi_local = xi;
  attempt->fit = FitQualityOf(
      MatchAtSolution(problem.last(), problem.points, xi, options.objective),
      options.quality_check.inlier_gate);
  attempt->held_covariance = HeldCovariance(options.initial_uncertainty,
                                            free,
                                            v,
                                            attempt->evaluation.hessian,
                                            xi,
                                            lever);
  attempt->prior_held_directions = static_cast<int>(free.cols());
  return attempt->prior_held_directions;
}

}  // namespace internal
}  // namespace mlndt
