#include "mlndt/registration/quality_check.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <cstdio>
#include <limits>
#include <sstream>

#include "mlndt/common/internal/check_option.h"
#include "mlndt/common/option_table.h"
#include "mlndt/common/pose.h"
#include "mlndt/cost/cell_match.h"

namespace mlndt {

const OptionTable& QualityCheckOptionsTable() {
  using S = QualityCheckOptions;
  static const OptionTable table =
      OptionTableBuilder<S>("QualityCheckOptions")
          .Bool("enabled",
                &S::enabled,
                "Report LOW_QUALITY/DEGENERATE instead of CONVERGENCE when "
                "the fit at the solution fails the check; off: the solver's "
                "termination is reported as it is.")
          .Double("inlier_gate",
                  &S::inlier_gate,
                  "",
                  Closed(0.5, 10.0),
                  "Mahalanobis distance below which a point is an inlier.")
          .Double("min_inlier_fraction",
                  &S::min_inlier_fraction,
                  "",
                  Closed(0.0, 1.0),
                  "LOW_QUALITY below this share of inliers.")
          .Double("max_mean_score",
                  &S::max_mean_score,
                  "",
                  LeftOpen(0.0, 1e6),
                  "LOW_QUALITY above this mean score per matched point.")
          .Double("min_constraint_ratio",
                  &S::min_constraint_ratio,
                  "",
                  RightOpen(0.0, 1.0),
                  "DEGENERATE below this weakest/strongest information "
                  "ratio.")
          .Validator(&S::IsValid)
          .Build();
  return table;
}

bool QualityCheckOptions::IsValid(std::string* error) const {
  return QualityCheckOptionsTable().Check(*this, error);
}

ConstraintAnalysis AnalyseConstraints(
    const NdtLayer& layer,
    const std::vector<Eigen::Vector3d>& input_points,
    const Vector6d& reference_from_input_xi,
    const ObjectiveOptions& objective,
    double rms_range_m,
    double min_constraint_ratio) {
  ConstraintAnalysis analysis;
  const Isometry3d pose = PoseVectorToIsometry(reference_from_input_xi);
  const double inverse_lever = 1.0 / std::max(rms_range_m, 1e-3);
  Matrix6d information = Matrix6d::Zero();
  for (const Eigen::Vector3d& p : input_points) {
    const Eigen::Vector3d turned = pose.linear() * p;  // R p.
    const NdtCell* cell = MatchCell(
        layer, turned + pose.translation(), objective.unmatched_policy);
    if (cell == nullptr) continue;
    // Row k of W is v_k^T / sqrt(lambda_k) (ndt_cell.h).
    const Eigen::Vector3d inverse_variances =
        cell->whitening.rowwise().squaredNorm();
    const double largest_variance = 1.0 / inverse_variances.minCoeff();
    for (int k = 0; k < 3; ++k) {
      if (1.0 / inverse_variances(k) >= kThinCellDirection * largest_variance) {
        continue;
      }
      const Eigen::Vector3d v = cell->whitening.row(k).transpose().normalized();
      Vector6d row;
      row << v, turned.cross(v) * inverse_lever;
      information.selfadjointView<Eigen::Lower>().rankUpdate(row);
    }
  }
  information = information.selfadjointView<Eigen::Lower>();
  const Eigen::SelfAdjointEigenSolver<Matrix6d> solver(information);
  const Vector6d lambda = solver.eigenvalues();  // Ascending.
  const double largest = lambda(5);
  for (int i = 0; i < 6; ++i) {
    if (!(lambda(i) >= min_constraint_ratio * largest) || !(largest > 0.0)) {
      analysis.degenerate_directions.push_back(solver.eigenvectors().col(i));
    }
  }
  if (largest > 0.0) {
    analysis.constraint_ratio = std::max(0.0, lambda(0)) / largest;
  }
  return analysis;
}

namespace {

// To two decimals, without a "-0.00".
Eigen::Vector3d Rounded(const Eigen::Vector3d& v) {
  return ((v * 100.0).array().round() / 100.0 + 0.0).matrix();
}

}  // namespace

std::string DescribeDirection(const Vector6d& direction) {
  // A direction and its opposite are the same: show the largest component
  // positive, and no "-0.00".
  Vector6d d = direction.normalized();
  Eigen::Index largest = 0;
  d.cwiseAbs().maxCoeff(&largest);
  if (d(largest) < 0.0) d = -d;
  const double translation = d.head<3>().norm();
  char text[160];
  if (translation >= d.tail<3>().norm()) {
    const Eigen::Vector3d t = Rounded(d.head<3>() / translation);
    std::snprintf(text,
                  sizeof(text),
                  "translation along (%.2f, %.2f, %.2f)",
                  t.x(),
                  t.y(),
                  t.z());
  } else {
    const Eigen::Vector3d r = Rounded(d.tail<3>().normalized());
    std::snprintf(text,
                  sizeof(text),
                  "rotation about (%.2f, %.2f, %.2f)",
                  r.x(),
                  r.y(),
                  r.z());
  }
  return text;
}

TerminationType CheckQuality(const QualityCheckOptions& options,
                             TerminationType solver_termination,
                             const FitQuality& fit,
                             const ConstraintAnalysis& constraints,
                             std::string* message) {
  if (!options.enabled) return solver_termination;
  std::ostringstream why;
  if (!constraints.degenerate_directions.empty()) {
    why << "degenerate: the fit does not constrain ";
    for (size_t i = 0; i < constraints.degenerate_directions.size(); ++i) {
      why << (i ? "; " : "")
          << DescribeDirection(constraints.degenerate_directions[i]);
    }
    why << " (constraint ratio " << constraints.constraint_ratio << " < "
        << options.min_constraint_ratio << ")";
    *message = why.str();
    return TerminationType::DEGENERATE;
  }
  if (fit.inlier_fraction < options.min_inlier_fraction) {
    why << "low quality: " << fit.inlier_fraction
        << " of the sampled points are inliers at the solution (below "
        << options.min_inlier_fraction << "); the pose is probably wrong";
  } else if (fit.mean_score > options.max_mean_score) {
    why << "low quality: mean score " << fit.mean_score
        << " per matched point at the solution (above "
        << options.max_mean_score << "); the pose is probably wrong";
  } else {
    return solver_termination;
  }
  *message = why.str();
  return TerminationType::LOW_QUALITY;
}

Judgement JudgeSolution(const QualityCheckOptions& options,
                        TerminationType solver_termination,
                        const NdtLayer& layer,
                        const std::vector<Eigen::Vector3d>& input_points,
                        const Vector6d& reference_from_input_xi,
                        const ObjectiveOptions& objective,
                        double rms_range_m) {
  Judgement judgement;
  judgement.fit = EvaluateFitQuality(layer,
                                     input_points,
                                     reference_from_input_xi,
                                     objective,
                                     options.inlier_gate);
  judgement.constraints = AnalyseConstraints(layer,
                                             input_points,
                                             reference_from_input_xi,
                                             objective,
                                             rms_range_m,
                                             options.min_constraint_ratio);
  judgement.verdict = CheckQuality(options,
                                   solver_termination,
                                   judgement.fit,
                                   judgement.constraints,
                                   &judgement.message);
  return judgement;
}

Matrix6d LaplaceCovariance(const Matrix6d& hessian,
                           double scale,
                           const ConstraintAnalysis& constraints) {
  if (constraints.degenerate_directions.empty()) {
    const Eigen::LLT<Matrix6d> positive_definite(hessian);
    const Eigen::FullPivLU<Matrix6d> lu(hessian);
    if (positive_definite.info() == Eigen::Success && lu.isInvertible()) {
      const Matrix6d covariance = scale * lu.inverse();
      if (covariance.allFinite()) return covariance;
    }
  }
  const Eigen::SelfAdjointEigenSolver<Matrix6d> solver(hessian);
  const double largest = std::max(solver.eigenvalues()(5), 0.0);
  Matrix6d covariance = Matrix6d::Zero();
  Vector6d unconstrained = Vector6d::Zero();
  for (int i = 0; i < 6; ++i) {
    const double lambda = solver.eigenvalues()(i);
    const Vector6d v = solver.eigenvectors().col(i);
    if (lambda > 1e-12 * largest && largest > 0.0) {
      covariance += (scale / lambda) * v * v.transpose();
    } else {
      unconstrained = unconstrained.cwiseMax(v.cwiseAbs());
    }
  }
  for (const Vector6d& d : constraints.degenerate_directions) {
    unconstrained = unconstrained.cwiseMax(d.cwiseAbs());
  }
  for (int i = 0; i < 6; ++i) {
    if (unconstrained(i) > 0.1) {
      covariance(i, i) = std::numeric_limits<double>::infinity();
    }
  }
  return covariance;
}

}  // namespace mlndt
