#include "mlndt/registration/quality_check.h"

#include <Eigen/Eigenvalues>
#include <cstdio>
#include <sstream>

#include "mlndt/common/internal/check_option.h"

namespace mlndt {

bool QualityCheckOptions::IsValid(std::string* error) const {
  MLNDT_OPTION_IN_RANGE(inlier_gate, 0.5, 10.0);
  MLNDT_OPTION_IN_RANGE(min_inlier_fraction, 0.0, 1.0);
  MLNDT_OPTION_GT(max_mean_score, 0.0);
  MLNDT_OPTION_LE(max_mean_score, 1e6);
  MLNDT_OPTION_GE(min_constraint_ratio, 0.0);
  MLNDT_OPTION_LT(min_constraint_ratio, 1.0);
  return true;
}

ConstraintAnalysis AnalyseConstraints(const Matrix6d& hessian,
                                      double rms_range_m,
                                      double min_constraint_ratio) {
  ConstraintAnalysis analysis;
  Vector6d scale = Vector6d::Ones();
  scale.tail<3>().setConstant(1.0 / std::max(rms_range_m, 1e-3));
  const Matrix6d scaled = scale.asDiagonal() * hessian * scale.asDiagonal();
  if (!scaled.allFinite()) return analysis;
  const Eigen::SelfAdjointEigenSolver<Matrix6d> solver(
      0.5 * (scaled + scaled.transpose()));
  const Vector6d lambda = solver.eigenvalues();  // Ascending.
  const double largest = lambda(5);
  if (!(largest > 0.0)) {
    for (int i = 0; i < 6; ++i) {
      analysis.degenerate_directions.push_back(solver.eigenvectors().col(i));
    }
    return analysis;
  }
  analysis.constraint_ratio = std::max(0.0, lambda(0)) / largest;
  for (int i = 0; i < 6; ++i) {
    if (lambda(i) < min_constraint_ratio * largest) {
      analysis.degenerate_directions.push_back(solver.eigenvectors().col(i));
    }
  }
  return analysis;
}

std::string DescribeDirection(const Vector6d& direction) {
  const Vector6d d = direction.normalized();
  const double translation = d.head<3>().norm();
  char text[160];
  if (translation >= d.tail<3>().norm()) {
    const Eigen::Vector3d t = d.head<3>() / translation;
    std::snprintf(text,
                  sizeof(text),
                  "translation along (%.2f, %.2f, %.2f)",
                  t.x(),
                  t.y(),
                  t.z());
  } else {
    const Eigen::Vector3d r = d.tail<3>().normalized();
    std::snprintf(text,
                  sizeof(text),
                  "rotation about (%.2f, %.2f, %.2f) (alpha, beta, gamma)",
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

}  // namespace mlndt
