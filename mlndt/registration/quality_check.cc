#include "mlndt/registration/quality_check.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "mlndt/common/internal/check_option.h"
#include "mlndt/common/option_table.h"
#include "mlndt/common/pose.h"
#include "mlndt/cost/point_matches.h"
#include "mlndt/cost/transform_derivatives.h"
#include "mlndt/registration/internal/cell_shape.h"
#include "mlndt/registration/internal/direction_probe.h"
#include "mlndt/registration/internal/unlocalizable_directions.h"

namespace mlndt {

using internal::AddUnlocalizableDirections;
using internal::AlreadyNamed;
using internal::InlierFlags;
using internal::MatchAtSolution;
using internal::Probe;
using internal::ProbeDirection;
using internal::ThinCellDirections;

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
          .Double("max_median_distance",
                  &S::max_median_distance,
                  "",
                  LeftOpen(0.0, 100.0),
                  "LOW_QUALITY above this median Mahalanobis distance of the "
                  "matched points to their cells (sigma).")
          .Double("min_inlier_fraction",
                  &S::min_inlier_fraction,
                  "",
                  Closed(0.0, 1.0),
                  "LOW_QUALITY below this share of inliers (too little "
                  "overlap to judge).")
          .Double("max_mean_score",
                  &S::max_mean_score,
                  "",
                  LeftOpen(0.0, 1e6),
                  "LOW_QUALITY above this mean score per matched point; 1e6 "
                  "= off.")
          .Double("min_constraint_ratio",
                  &S::min_constraint_ratio,
                  "",
                  RightOpen(0.0, 1.0),
                  "DEGENERATE below this weakest/strongest information "
                  "ratio.")
          .Double("min_localizability",
                  &S::min_localizability,
                  "",
                  RightOpen(0.0, 1.0),
                  "DEGENERATE when fewer than this share of the inliers on "
                  "planar cells constrain a direction of the pose through "
                  "their normal (localizability, dimensionless); 0 = off.")
          .Double("max_flatness",
                  &S::max_flatness,
                  "",
                  LeftOpen(0.0, 1.0),
                  "DEGENERATE when one last-layer cell along a weak direction "
                  "keeps more than this share of the inliers both ways and "
                  "the net loss is under min_probe_evidence (a corridor keeps "
                  "0.99, right results at most 0.93: docs/trust.md); 1 = "
                  "off.")
          .Double("min_probe_evidence",
                  &S::min_probe_evidence,
                  "sigma",
                  AtLeast(0.0),
                  "A weak direction whose probe loses inliers by at least "
                  "this many standard deviations of the exchange is not "
                  "flat.")
          .Int("min_fit_points",
               &S::min_fit_points,
               Closed(0, 1e6),
               "LOW_QUALITY with fewer sampled points than this: too few to "
               "judge the fit.")
          .Validator(&S::IsValid)
          .Build();
  return table;
}

bool QualityCheckOptions::IsValid(std::string* error) const {
  return QualityCheckOptionsTable().Check(*this, error);
}

namespace {

// Directions whose eigenvalue is below this fraction of the largest are
// probed (at most the three weakest).
constexpr double kProbedConstraintRatio = 0.25;

// The sums of the rows [v; (R p) x v / L] over the thin directions v of the
// matched points' cells (quality_check.h), planar and line cells apart.
struct ThinDirectionSums {
  Matrix6d planar = Matrix6d::Zero();  // Cells thin in one direction.
  Matrix6d lines = Matrix6d::Zero();   // Cells thin in two.
};

ThinDirectionSums ThinDirectionInformation(
    const std::vector<Eigen::Vector3d>& input_points,
    const std::vector<PointMatch>& matches,
    const Matrix3d& rotation,
    double rms_range_m) {
  const double inverse_lever = 1.0 / std::max(rms_range_m, 1e-3);
  ThinDirectionSums sums;
  for (size_t k = 0; k < input_points.size(); ++k) {
    const NdtCell* cell = matches[k].cell;
    if (cell == nullptr) continue;
    const Eigen::Array<bool, 3, 1> thin = ThinCellDirections(*cell);
    Matrix6d& sum = thin.count() == 2 ? sums.lines : sums.planar;
    const Eigen::Vector3d turned = rotation * input_points[k];  // R p.
    for (int i = 0; i < 3; ++i) {
      if (!thin(i)) continue;
      const Eigen::Vector3d v = cell->whitening.row(i).transpose().normalized();
      Vector6d row;
      row << v, turned.cross(v) * inverse_lever;
      sum.selfadjointView<Eigen::Lower>().rankUpdate(row);
    }
  }
  sums.planar = sums.planar.selfadjointView<Eigen::Lower>();
  sums.lines = sums.lines.selfadjointView<Eigen::Lower>();
  return sums;
}

// AnalyseConstraints on points already matched at the pose.
ConstraintAnalysis AnalyseMatched(
    const NdtLayer& layer,
    const std::vector<Eigen::Vector3d>& input_points,
    const std::vector<PointMatch>& matches,
    const Vector6d& reference_from_input_xi,
    const ObjectiveOptions& objective,
    double rms_range_m,
    const QualityCheckOptions& options) {
  ConstraintAnalysis analysis;
  const Isometry3d pose = PoseVectorToIsometry(reference_from_input_xi);
  const ThinDirectionSums sums = ThinDirectionInformation(
      input_points, matches, pose.linear(), rms_range_m);
  // Whether the surfaces leave a direction free: planar cells only (a line
  // cell's second thin direction is mostly the gap between scan rings).
  const Eigen::SelfAdjointEigenSolver<Matrix6d> surfaces(sums.planar);
  const Vector6d mu = surfaces.eigenvalues();  // Ascending.
  for (int i = 0; i < 6; ++i) {
    if (!(mu(i) >= options.min_constraint_ratio * mu(5)) || !(mu(5) > 0.0)) {
      analysis.degenerate_directions.push_back(surfaces.eigenvectors().col(i));
    }
  }
  if (!(mu(5) > 0.0)) return analysis;
  AddUnlocalizableDirections(matches, options, &analysis);
  analysis.weakest_translations =
      Eigen::SelfAdjointEigenSolver<Matrix3d>(sums.planar.topLeftCorner<3, 3>())
          .eigenvectors();
  analysis.constraint_ratio = std::max(0.0, mu(0)) / mu(5);
  if (options.max_flatness >= 1.0) return analysis;  // The probe is off.
  // The probe's candidates: the weakest directions with line cells counted,
  // since it measures what moving along them costs every inlier.
  const Eigen::SelfAdjointEigenSolver<Matrix6d> solver(sums.planar +
                                                       sums.lines);
  const Vector6d lambda = solver.eigenvalues();  // Ascending.
  const double largest = lambda(5);
  const std::vector<bool> inlier = InlierFlags(matches, options.inlier_gate);
  // The ratio has already named this many free directions: the probe names
  // only weaker-ranked ones beyond them.
  const size_t by_ratio =
      analysis.degenerate_directions.size() - analysis.unlocalizable_directions;
  for (int i = 0; i < 3 && lambda(i) < kProbedConstraintRatio * largest; ++i) {
    const Vector6d d = solver.eigenvectors().col(i);
    const Probe probe = ProbeDirection(layer,
                                       input_points,
                                       pose,
                                       objective,
                                       rms_range_m,
                                       options.inlier_gate,
                                       inlier,
                                       d);
    if (probe.kept > analysis.flatness) {
      analysis.flatness = probe.kept;
      analysis.probe_evidence = probe.evidence;
      analysis.flattest_direction = d;
    }
    if (static_cast<size_t>(i) >= by_ratio &&
        probe.kept > options.max_flatness &&
        probe.evidence < options.min_probe_evidence &&
        !AlreadyNamed(analysis.degenerate_directions, d)) {
      analysis.degenerate_directions.push_back(d);
      analysis.flat_directions++;
    }
  }
  return analysis;
}

}  // namespace

ConstraintAnalysis AnalyseConstraints(
    const NdtLayer& layer,
    const std::vector<Eigen::Vector3d>& input_points,
    const Vector6d& reference_from_input_xi,
    const ObjectiveOptions& objective,
    double rms_range_m,
    const QualityCheckOptions& options) {
  return AnalyseMatched(
      layer,
      input_points,
      MatchAtSolution(layer, input_points, reference_from_input_xi, objective),
      reference_from_input_xi,
      objective,
      rms_range_m,
      options);
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
    if (constraints.flat_directions > 0) {
      why << " (moving the pose one cell along it keeps "
          << std::lround(100.0 * constraints.flatness) << " % of the inliers)";
    } else if (constraints.unlocalizable_directions > 0) {
      why << " (" << 100.0 * constraints.localizability
          << " % of the inliers on planar surfaces constrain it through "
             "their normal, below "
          << 100.0 * options.min_localizability << " %)";
    } else {
      why << " (constraint ratio " << constraints.constraint_ratio << " < "
          << options.min_constraint_ratio << ")";
    }
    *message = why.str();
    return TerminationType::DEGENERATE;
  }
  if (fit.points < static_cast<size_t>(options.min_fit_points)) {
    why << "low quality: " << fit.points
        << " sampled points, too few to check the fit (below "
        << options.min_fit_points << ")";
  } else if (fit.inlier_fraction < options.min_inlier_fraction) {
    why << "low quality: " << fit.inlier_fraction
        << " of the sampled points are inliers at the solution (below "
        << options.min_inlier_fraction << "); the pose is probably wrong";
  } else if (fit.median_distance > options.max_median_distance) {
    why << "low quality: the matched points' median Mahalanobis distance "
        << fit.median_distance << " at the solution is above "
        << options.max_median_distance << "; the pose is probably wrong";
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
  // One cell lookup per point serves the fit and the constraint analysis.
  const std::vector<PointMatch> matches =
      MatchAtSolution(layer, input_points, reference_from_input_xi, objective);
  judgement.fit = FitQualityOf(matches, options.inlier_gate);
  judgement.constraints = AnalyseMatched(layer,
                                         input_points,
                                         matches,
                                         reference_from_input_xi,
                                         objective,
                                         rms_range_m,
                                         options);
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
