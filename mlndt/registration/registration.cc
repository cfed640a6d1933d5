#include "mlndt/registration/registration.h"

#include <glog/logging.h>

#include <memory>

#include "mlndt/common/pose.h"
#include "mlndt/common/timer.h"
#include "mlndt/cost/score.h"
#include "mlndt/registration/internal/registration_steps.h"

namespace mlndt {
namespace {

constexpr char kEntryPoint[] = "mlndt::Register";

void Fail(const std::string& message, RegistrationSummary* summary) {
  internal::Fail(kEntryPoint, message, summary);
}

// The pose, score, counts, Hessian and covariance at the solution xi, on the
// last layer.
void ReportSolution(const RegistrationOptions& options,
                    const NdtLayer& last,
                    const std::vector<Eigen::Vector3d>& points,
                    const Vector6d& xi,
                    RegistrationSummary* summary) {
  const ScoreEvaluation final =
      EvaluateScore(last, points, xi, options.objective);
  summary->reference_from_input_xi = xi;
  summary->reference_from_input = PoseVectorToIsometry(xi);
  summary->final_score = final.score;
  summary->matched_points = final.matched;
  summary->unmatched_points = final.unmatched;
  summary->hessian = final.hessian;
  const Eigen::FullPivLU<Matrix6d> lu(final.hessian);
  summary->covariance =
      lu.isInvertible() ? Matrix6d(2.0 * lu.inverse()) : Matrix6d::Zero();
  summary->quality =
      EvaluateFitQuality(last, points, xi, options.objective, 3.0);
}

// The whole ML-NDT registration after the map exists (Table 1); times are
// added to *summary.
void RegisterOnMap(const RegistrationOptions& options,
                   const LayeredGrid& reference_map,
                   const PointCloud& input,
                   const Isometry3d& initial_reference_from_input,
                   double start_time_s,
                   RegistrationSummary* summary) {
  std::string error;
  if (reference_map.empty()) return Fail("the reference map is empty", summary);
  std::unique_ptr<Backend> backend = CreateBackend(options.backend, &error);
  if (!backend) return Fail(error, summary);
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

  const Vector6d initial_xi =
      IsometryToPoseVector(initial_reference_from_input);
  const NdtLayer& last = reference_map.layer(reference_map.num_layers());
  summary->initial_reference_from_input_xi = initial_xi;
  internal::DescribeMap(reference_map, summary);
  summary->start_layer =
      ResolveStartLayer(options.schedule, reference_map.num_layers());
  summary->initial_score =
      EvaluateScore(last, sampled.points(), initial_xi, options.objective)
          .score;

  const double t0 = NowSeconds();
  backend->SetProblem(sampled.points(), options.objective, options.num_threads);
  Vector6d xi = initial_xi;
  ScheduleSummary schedule;
  RunLayerSchedule(options.schedule,
                   reference_map,
                   start_time_s,
                   backend.get(),
                   &xi,
                   &schedule);
  summary->solve_time_s = NowSeconds() - t0;
  summary->trace = schedule.trace;
  summary->iterations_per_layer = schedule.iterations_per_layer;
  summary->num_iterations = static_cast<int>(schedule.trace.size());
  if (schedule.termination_type == TerminationType::FAILURE) {
    return Fail(schedule.message, summary);
  }
  if (!xi.allFinite()) {
    return Fail("the solver returned a non-finite pose", summary);
  }
  ReportSolution(options, last, sampled.points(), xi, summary);
  summary->termination_type = schedule.termination_type;
  summary->message = schedule.message;
  const std::string unmatched =
      internal::CheckMatchedFraction(options.min_matched_fraction, *summary);
  if (!unmatched.empty()) Fail(unmatched, summary);
}

}  // namespace

void Register(const RegistrationOptions& options,
              const LayeredGrid& reference_map,
              const PointCloud& input,
              const Isometry3d& initial_reference_from_input,
              RegistrationSummary* summary) {
  CHECK(summary != nullptr);
  *summary = RegistrationSummary();
  const double start = NowSeconds();
  std::string error;
  if (!options.IsValid(&error)) {
    Fail(error, summary);
  } else {
    RegisterOnMap(options,
                  reference_map,
                  input,
                  initial_reference_from_input,
                  start,
                  summary);
  }
  summary->total_time_s = NowSeconds() - start;
}

void Register(const RegistrationOptions& options,
              const PointCloud& reference,
              const PointCloud& input,
              const Isometry3d& initial_reference_from_input,
              RegistrationSummary* summary) {
  CHECK(summary != nullptr);
  *summary = RegistrationSummary();
  const double start = NowSeconds();
  std::string error;
  PointCloud filtered;
  LayeredGrid map;
  if (!options.IsValid(&error)) {
    Fail(error, summary);
  } else if (!internal::FilterReference(
                 options.range_filter, reference, &filtered, &error) ||
             !LayeredGrid::Build(
                 options.grid, filtered, options.num_threads, &map, &error)) {
    Fail("reference map: " + error, summary);
  } else {
    summary->map_time_s = NowSeconds() - start;
    RegisterOnMap(
        options, map, input, initial_reference_from_input, start, summary);
  }
  summary->total_time_s = NowSeconds() - start;
}

}  // namespace mlndt
