#include "mlndt/ndt/ndt_registration.h"

#include <glog/logging.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "mlndt/common/internal/check_option.h"
#include "mlndt/common/option_table.h"
#include "mlndt/common/pose.h"
#include "mlndt/common/timer.h"
#include "mlndt/ndt/ndt_objective.h"
#include "mlndt/registration/internal/registration_steps.h"

namespace mlndt {
namespace {

constexpr char kEntryPoint[] = "mlndt::RegisterNdt";

void Fail(const std::string& message, RegistrationSummary* summary) {
  internal::Fail(kEntryPoint, message, summary);
}

GaussianScoreOptions ScoreOptionsFor(const NdtOptions& options) {
  GaussianScoreOptions score;
  score.outlier_ratio = options.outlier_ratio;
  score.neighbors = options.neighbors;
  score.num_threads = options.num_threads;
  return score;
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

// Minimises the Gaussian score of the sampled points on `grid` with Newton
// and fills *summary (one layer). Returns "" or the failure's message.
std::string MinimizeOnGrid(const NdtOptions& options,
                           const NdtLayer& grid,
                           const std::vector<Eigen::Vector3d>& points,
                           const Vector6d& initial_xi,
                           double start_time_s,
                           RegistrationSummary* summary) {
  const NdtGaussianObjective objective(grid, points, ScoreOptionsFor(options));
  summary->initial_reference_from_input_xi = initial_xi;
  summary->start_layer = 1;
  summary->initial_score =
      objective.Evaluate(initial_xi, HessianType::NONE).score;

  StageControl control;
  control.max_iterations = options.max_iterations;
  control.step_tolerance = options.step_tolerance;
  Vector6d xi = initial_xi;
  StageSummary newton;
  const double t0 = NowSeconds();
  const StepBoundedObjective bounded(objective, options.max_step_norm);
  MinimizeNewton(bounded, options.newton, control, &xi, &newton);
  summary->solve_time_s = NowSeconds() - t0;
  for (IterationRecord record : newton.trace) {
    record.layer = 1;
    record.iteration = static_cast<int>(summary->trace.size()) + 1;
    record.time_s += t0 - start_time_s;
    summary->trace.push_back(record);
  }
  summary->iterations_per_layer = {newton.iterations()};
  summary->num_iterations = newton.iterations();
  if (newton.termination_type == TerminationType::FAILURE) {
    return newton.message;
  }
  if (!xi.allFinite()) return "the solver returned a non-finite pose";

  // Results at the solution, with the full Newton Hessian (Eq. 6.13).
  const ScoreEvaluation final = objective.Evaluate(xi, HessianType::FULL);
  summary->reference_from_input_xi = xi;
  summary->reference_from_input = PoseVectorToIsometry(xi);
  summary->final_score = final.score;
  summary->matched_points = final.matched;
  summary->unmatched_points = final.unmatched;
  summary->hessian = final.hessian;
  summary->termination_type = newton.termination_type;
  summary->message = newton.message;
  return "";
}

// The verdict on `verdict_layer` (nullptr: cells too coarse to check), and
// the covariance: the Gaussian score approximates the negative
// log-likelihood of the input points up to a constant (Magnusson Eq. 6.8),
// so H^-1 is its Laplace covariance; infinite where H is not positive
// definite or the fit leaves a direction free.
void Judge(const NdtOptions& options,
           const NdtLayer* verdict_layer,
           const std::vector<Eigen::Vector3d>& points,
           RegistrationSummary* summary) {
  if (verdict_layer == nullptr) {
    summary->covariance =
        LaplaceCovariance(summary->hessian, 1.0, ConstraintAnalysis());
    if (options.quality_check.enabled &&
        summary->termination_type == TerminationType::CONVERGENCE) {
      summary->termination_type = TerminationType::NO_CONVERGENCE;
      summary->message =
          "not checked: the map's cells are too coarse for the fit check "
          "(register from the reference cloud for a verdict); solver: " +
          summary->message;
    }
    return;
  }
  double squares = 0.0;
  for (const Eigen::Vector3d& p : points) squares += p.squaredNorm();
  const double rms_range_m =
      std::sqrt(squares / static_cast<double>(points.size()));
  Judgement judgement = JudgeSolution(options.quality_check,
                                      summary->termination_type,
                                      *verdict_layer,
                                      points,
                                      summary->reference_from_input_xi,
                                      ObjectiveOptions(),
                                      rms_range_m);
  summary->quality = judgement.fit;
  summary->constraints = judgement.constraints;
  summary->covariance =
      LaplaceCovariance(summary->hessian, 1.0, judgement.constraints);
  if (judgement.verdict != summary->termination_type) {
    summary->termination_type = judgement.verdict;
    summary->message =
        judgement.message + " (solver: " + summary->message + ")";
  }
}

// The layer an NDT result on `map` is judged on: its own when the cells are
// at most twice ML-NDT's finest cell, else none.
const NdtLayer* VerdictLayerOf(const LayeredGrid& map) {
  const double finest = LayeredGridOptions().finest_cell_size_m;
  return map.layer_info().back().cell_size_m <= 2.0 * finest
             ? &map.layer(map.num_layers())
             : nullptr;
}

// Registration once the grid exists; times are added to *summary.
void RegisterOnGrid(const NdtOptions& options,
                    const LayeredGrid& map,
                    const NdtLayer* verdict_layer,
                    const PointCloud& input,
                    const Isometry3d& initial_reference_from_input,
                    double start_time_s,
                    RegistrationSummary* summary) {
  std::string error;
  if (!internal::CheckMap(map, &error)) return Fail(error, summary);
  PointCloud sampled;
  if (!internal::SampleInput(options.range_filter,
                             options.sampling,
                             input,
                             initial_reference_from_input,
                             &sampled,
                             summary,
                             &error)) {
    return Fail(error, summary);
  }
  internal::DescribeMap(map, summary);
  error = MinimizeOnGrid(options,
                         map.layer(map.num_layers()),
                         sampled.points(),
                         IsometryToPoseVector(initial_reference_from_input),
                         start_time_s,
                         summary);
  if (error.empty()) {
    error =
        internal::CheckMatchedFraction(options.min_matched_fraction, *summary);
  }
  if (!error.empty()) return Fail(error, summary);
  Judge(options, verdict_layer, sampled.points(), summary);
}

}  // namespace

const OptionTable& NdtOptionsTable() {
  using S = NdtOptions;
  static const OptionTable table =
      OptionTableBuilder<S>("NdtOptions")
          .Struct("range_filter",
                  &S::range_filter,
                  RangeFilterOptionsTable(),
                  "Returns dropped from both clouds.")
          .Double("cell_size_m",
                  &S::cell_size_m,
                  "m",
                  ClosedOrZero(1e-3, 1e5),
                  "Cell edge; 0 = the paper's layer-2 cell (V / 64)^(1/3).")
          .Int("min_points_per_cell",
               &S::min_points_per_cell,
               Closed(4, 1000000),
               "A cell keeps a distribution with at least this many points.")
          .Struct("regularization",
                  &S::regularization,
                  CellRegularizationTable(),
                  "Covariance regularisation (ndt_cell.h).")
          .Double("outlier_ratio",
                  &S::outlier_ratio,
                  "",
                  {0.0, 1.0, true, true},
                  "Magnusson's outlier ratio (PCL: 0.55).")
          .Enum("neighbors",
                &S::neighbors,
                NdtNeighborsTable(),
                "Cells a point is scored in: direct1 (its own) or direct7 "
                "(+6 faces).")
          .Struct("sampling",
                  &S::sampling,
                  SamplingOptionsTable(),
                  "Which input points become residuals.")
          .Int("max_iterations",
               &S::max_iterations,
               Closed(1, 10000),
               "Newton iteration cap.")
          .Double("step_tolerance",
                  &S::step_tolerance,
                  "m and rad",
                  Closed(1e-12, 1.0),
                  "Converged when a Newton step is shorter than this.")
          .Double("max_step_norm",
                  &S::max_step_norm,
                  "m and rad",
                  Closed(0.0, 1e3),
                  "Longest Newton step ||delta xi||; 0 = unbounded.")
          .Struct(
              "newton", &S::newton, NewtonOptionsTable(), "Newton's options.")
          .Int("num_threads",
               &S::num_threads,
               Closed(1, 256),
               "Threads for the map build and the score.")
          .Double("min_matched_fraction",
                  &S::min_matched_fraction,
                  "",
                  Closed(0.0, 1.0),
                  "FAILURE when fewer than this fraction of the sampled "
                  "points are matched at the solution.")
          .Struct("quality_check",
                  &S::quality_check,
                  QualityCheckOptionsTable(),
                  "Whether the result can be trusted (quality_check.h).")
          .Validator(&S::IsValid)
          .Build();
  return table;
}

bool NdtOptions::IsValid(std::string* error) const {
  return NdtOptionsTable().Check(*this, error) && range_filter.IsValid(error) &&
         sampling.IsValid(error) && newton.IsValid(error) &&
         quality_check.IsValid(error);
}

bool NdtGridOptions(const NdtOptions& options,
                    const PointCloud& reference,
                    LayeredGridOptions* grid_options,
                    std::string* error) {
  *grid_options = LayeredGridOptions();
  grid_options->min_points_per_cell = options.min_points_per_cell;
  grid_options->regularization = options.regularization;
  grid_options->cell_size_m = options.cell_size_m;
  if (options.cell_size_m > 0.0) return true;
  // The paper's comparison cell: layer 2 of q = 8 over the same box.
  if (reference.empty() || !AllFinite(reference)) {
    *error = reference.empty() ? "the reference cloud is empty"
                               : "the reference cloud has non-finite points";
    return false;
  }
  LayeredGridOptions paper = PaperLayeredGridOptions();
  paper.num_layers = 2;
  const std::vector<double> sizes =
      LayerCellSizes(paper, BoundingBox(reference).sizes());
  if (sizes.size() != 2) {
    *error = "all reference points coincide: the bounding box has no volume";
    return false;
  }
  grid_options->cell_size_m = sizes[1];
  return true;
}

void RegisterNdt(const NdtOptions& options,
                 const PointCloud& reference,
                 const PointCloud& input,
                 const Isometry3d& initial_reference_from_input,
                 RegistrationSummary* summary) {
  CHECK(summary != nullptr);
  *summary = RegistrationSummary();
  summary->algorithm = "NDT";
  const double start = NowSeconds();
  std::string error;
  LayeredGridOptions grid_options;
  PointCloud filtered;
  LayeredGrid map, verdict_map;
  if (!options.IsValid(&error)) {
    Fail(error, summary);
  } else if (!internal::FilterReference(
                 options.range_filter, reference, &filtered, &error) ||
             !NdtGridOptions(options, filtered, &grid_options, &error) ||
             !LayeredGrid::Build(
                 grid_options, filtered, options.num_threads, &map, &error) ||
             !LayeredGrid::Build(LayeredGridOptions(),
                                 filtered,
                                 options.num_threads,
                                 &verdict_map,
                                 &error)) {
    Fail("reference map: " + error, summary);
  } else {
    summary->map_time_s = NowSeconds() - start;
    RegisterOnGrid(options,
                   map,
                   &verdict_map.layer(verdict_map.num_layers()),
                   input,
                   initial_reference_from_input,
                   start,
                   summary);
  }
  summary->total_time_s = NowSeconds() - start;
}

void RegisterNdt(const NdtOptions& options,
                 const LayeredGrid& reference_map,
                 const PointCloud& input,
                 const Isometry3d& initial_reference_from_input,
                 RegistrationSummary* summary) {
  CHECK(summary != nullptr);
  *summary = RegistrationSummary();
  summary->algorithm = "NDT";
  const double start = NowSeconds();
  std::string error;
  if (!options.IsValid(&error)) {
    Fail(error, summary);
  } else {
    RegisterOnGrid(options,
                   reference_map,
                   VerdictLayerOf(reference_map),
                   input,
                   initial_reference_from_input,
                   start,
                   summary);
  }
  summary->total_time_s = NowSeconds() - start;
}

}  // namespace mlndt
