#include "mlndt/common/result_table.h"
#include "mlndt/registration/registration_summary.h"

namespace mlndt {
namespace {

using S = RegistrationSummary;
using Builder = ResultTableBuilder<S>;

void AddVerdictAndPose(Builder* b) {
  b->Enum("termination_type",
          &S::termination_type,
          TerminationTypeTable(),
          "How it ended: CONVERGENCE, NO_CONVERGENCE, LOW_QUALITY, "
          "DEGENERATE or FAILURE.")
      .String("message", &S::message, "Why it ended.")
      .String("algorithm", &S::algorithm, "ML-NDT or NDT.")
      .Computed("usable",
                ResultType::BOOL,
                "",
                "IsSolutionUsable(): CONVERGENCE or NO_CONVERGENCE, the pose "
                "passed the quality check.",
                [](const S& s) { return ResultValue(s.IsSolutionUsable()); })
      .Vector("initial_reference_from_input_xi",
              &S::initial_reference_from_input_xi,
              "m, rad",
              "The initial guess as a pose vector (tx, ty, tz, alpha, beta, "
              "gamma), Eq. 11.")
      .Vector("reference_from_input_xi",
              &S::reference_from_input_xi,
              "m, rad",
              "The result as a pose vector (tx, ty, tz, alpha, beta, gamma), "
              "Eq. 11.")
      .Computed("reference_from_input",
                ResultType::MATRIX,
                "m",
                "4x4 rigid transform (row-major) mapping input points into "
                "the reference frame.",
                [](const S& s) {
                  return ResultValue(
                      Eigen::MatrixXd(s.reference_from_input.matrix()));
                });
}

void AddIterations(Builder* b) {
  b->StructList("trace",
                &S::trace,
                IterationRecordTable(),
                "One record per iteration of the reported solution.")
      .IntegerList("iterations_per_layer",
                   &S::iterations_per_layer,
                   "Iterations on each layer, layer 1 (coarsest) first.")
      .Integer("num_iterations",
               &S::num_iterations,
               "",
               "Iterations of the reported solution, all layers together.")
      .Integer("attempts",
               &S::attempts,
               "",
               "Schedule runs (guess comparisons and yaw retries included).")
      .Integer("point_iterations",
               &S::point_iterations,
               "",
               "Sampled points evaluated, summed over every iteration of "
               "every attempt (0 for NDT).")
      .Integer("start_layer", &S::start_layer, "", "The layer it started on.")
      .Integer("prior_held_directions",
               &S::prior_held_directions,
               "",
               "Free directions along which the pose kept the prior's value "
               "(and the covariance the prior's); 0 without a prior.")
      .Integer("num_layers", &S::num_layers, "", "Layers of the map.")
      .Number("finest_cell_size_m",
              &S::finest_cell_size_m,
              "m",
              "Cell edge of the last layer.");
}

void AddPointsAndTimes(Builder* b) {
  b->Integer("input_points", &S::input_points, "", "Points of the input.")
      .Integer("range_filtered_points",
               &S::range_filtered_points,
               "",
               "Input points dropped by the range filter.")
      .Integer("sampled_points",
               &S::sampled_points,
               "",
               "Input points that became residuals.")
      .Integer("matched_points",
               &S::matched_points,
               "",
               "Sampled points in a cell of the last layer at the solution.")
      .Integer("unmatched_points",
               &S::unmatched_points,
               "",
               "Sampled points in no cell at the solution.")
      .Number("map_time_s",
              &S::map_time_s,
              "s",
              "Building the reference map (0 when given).")
      .Number("sampling_time_s", &S::sampling_time_s, "s", "Sampling.")
      .Number("solve_time_s", &S::solve_time_s, "s", "The layer schedule.")
      .Number("total_time_s",
              &S::total_time_s,
              "s",
              "Everything after the clouds were loaded.");
}

void AddEvidence(Builder* b) {
  b->Struct("quality",
            &S::quality,
            FitQualityTable(),
            "The fit at the solution on the last layer: the verdict's "
            "evidence.")
      .Struct("constraints",
              &S::constraints,
              ConstraintAnalysisTable(),
              "How well the fit constrains the pose.")
      .Integer("map_occupied_cells",
               &S::map_occupied_cells,
               "",
               "Occupied cells over all layers of the reference map.")
      .Integer("map_bytes", &S::map_bytes, "bytes", "The map's memory.")
      .Number("initial_score",
              &S::initial_score,
              "",
              "The objective at the initial pose (ML-NDT: Eq. 10 on the last "
              "layer; NDT: the Gaussian score, <= 0).")
      .Number("final_score", &S::final_score, "", "The same at the solution.")
      .Matrix("hessian",
              &S::hessian,
              "m, rad",
              "6x6 Hessian of the final score w.r.t. the pose vector.")
      .Matrix("covariance",
              &S::covariance,
              "m, rad",
              "6x6 covariance of the pose vector (ML-NDT: 2 H^-1); infinite "
              "along degenerate directions, zero when H is singular.");
}

}  // namespace

const ResultTable& RegistrationSummaryTable() {
  static const ResultTable table = [] {
    Builder builder("RegistrationSummary");
    AddVerdictAndPose(&builder);
    AddIterations(&builder);
    AddPointsAndTimes(&builder);
    AddEvidence(&builder);
    return builder.Build();
  }();
  return table;
}

}  // namespace mlndt
