#include "mlndt/registration/registration.h"

#include <glog/logging.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "mlndt/common/pose.h"
#include "mlndt/common/timer.h"
#include "mlndt/cost/score.h"
#include "mlndt/registration/internal/attempts.h"
#include "mlndt/registration/internal/input_anchor.h"
#include "mlndt/registration/internal/registration_steps.h"
#include "mlndt/registration/prepared_input.h"
#include "mlndt/registration/prepared_registration.h"

namespace mlndt {
namespace {

constexpr char kEntryPoint[] = "mlndt::Register";

void Fail(const std::string& message, RegistrationSummary* summary) {
  internal::Fail(kEntryPoint, message, summary);
}

using internal::Attempt;
using internal::Problem;

// The pose, score, counts, fit, constraints, Hessian and covariance at the
// attempt's solution, on the last layer, in the input frame's
// parametrisation (Eq. 11).
void ReportSolution(const Problem& problem,
                    const Attempt& attempt,
                    RegistrationSummary* summary) {
  const Vector6d& local = attempt.xi_local;
  const ScoreEvaluation& final = attempt.evaluation;
  // xi = f(xi_local): H = J^-T H_local J^-1, C = J C_local J^T.
  const Matrix6d j = problem.anchor.Jacobian(local);
  const Matrix6d j_inverse = j.inverse();
  summary->constraints = attempt.constraints;
  summary->quality = attempt.fit;
  // 2 H^-1: the Laplace approximation for whitened residuals of unit
  // variance.
  // Held at the prior along free directions (attempts.h step 8): the
  // prior's covariance there, the Laplace one on the rest.
  const Matrix6d local_covariance =
      attempt.prior_held_directions > 0 && attempt.held_covariance.allFinite()
          ? attempt.held_covariance
          : LaplaceCovariance(final.hessian, 2.0, summary->constraints);
  summary->prior_held_directions = attempt.prior_held_directions;
  summary->reference_from_input =
      PoseVectorToIsometry(problem.anchor.ToGlobal(local));
  // Angles wrapped to (-pi, pi] by the round trip.
  summary->reference_from_input_xi =
      IsometryToPoseVector(summary->reference_from_input);
  summary->final_score = final.score;
  summary->matched_points = final.matched;
  summary->unmatched_points = final.unmatched;
  summary->hessian = j_inverse.transpose() * final.hessian * j_inverse;
  summary->covariance = local_covariance.allFinite()
                            ? Matrix6d(j * local_covariance * j.transpose())
                            : local_covariance;
}

// The attempt's trace with its poses in the input frame's parametrisation.
std::vector<IterationRecord> GlobalTrace(const Attempt& attempt,
                                         const internal::InputAnchor& anchor) {
  std::vector<IterationRecord> trace = attempt.schedule.trace;
  for (IterationRecord& record : trace) {
    record.reference_from_input_xi =
        anchor.ToGlobal(record.reference_from_input_xi);
  }
  return trace;
}

// The verdict: the solver's termination, then the matched-fraction and
// quality checks.
void Judge(const RegistrationOptions& options,
           const Attempt& attempt,
           RegistrationSummary* summary) {
  summary->termination_type = attempt.schedule.termination_type;
  summary->message = attempt.schedule.message;
  if (!std::isfinite(summary->final_score) ||
      !summary->reference_from_input.matrix().allFinite()) {
    return Fail("the solution is not finite (score " +
                    std::to_string(summary->final_score) + ")",
                summary);
  }
  const std::string unmatched =
      internal::CheckMatchedFraction(options.min_matched_fraction, *summary);
  if (!unmatched.empty()) return Fail(unmatched, summary);
  if (attempt.verdict != summary->termination_type) {
    summary->termination_type = attempt.verdict;
    summary->message =
        attempt.verdict_message + " (solver: " + summary->message + ")";
  }
}

// The map's check and the backend; null after Fail.
std::unique_ptr<Backend> CheckedBackend(const RegistrationOptions& options,
                                        const LayeredGrid& reference_map,
                                        RegistrationSummary* summary) {
  std::string error;
  if (!internal::CheckMap(reference_map, &error)) {
    Fail(error, summary);
    return nullptr;
  }
  std::unique_ptr<Backend> backend = CreateBackend(options.backend, &error);
  if (!backend) Fail(error, summary);
  return backend;
}

// The whole ML-NDT registration of a prepared input once the backend exists
// (Table 1); times are added to *summary. The input's problems, then the
// guess's, then the sampling's fail it, in SampleInput's order.
// `problem_is_set`: the backend holds input.points and options' objective
// already (PreparedRegistration), else they are set here.
void RegisterPrepared(const RegistrationOptions& options,
                      const LayeredGrid& reference_map,
                      Backend* backend,
                      const PreparedInput& input,
                      const Isometry3d& initial_reference_from_input,
                      double start_time_s,
                      RegistrationSummary* summary,
                      bool problem_is_set = false) {
  if (!input.input_error.empty()) return Fail(input.input_error, summary);
  std::string error;
  if (!internal::CheckInitialGuess(initial_reference_from_input, &error)) {
    return Fail(error, summary);
  }
  summary->input_points = input.input_points;
  summary->range_filtered_points = input.range_filtered_points;
  summary->sampled_points = input.sampled_points;
  summary->sampling_time_s = input.sampling_time_s;
  if (!input.sampling_error.empty()) return Fail(input.sampling_error, summary);
  const std::vector<Eigen::Vector3d>& points = input.points;
  const internal::InputAnchor anchor(input.centre);
  const Problem problem{
      reference_map, points, anchor, backend, input.rms_range_m, {}};
  const Vector6d initial_xi =
      IsometryToPoseVector(initial_reference_from_input);
  const Vector6d initial_local = anchor.ToLocal(initial_xi);
  summary->initial_reference_from_input_xi = initial_xi;
  internal::DescribeMap(reference_map, summary);
  summary->initial_score = EvaluateScore(problem.last(),
                                         points,
                                         initial_local,
                                         options.objective,
                                         HessianType::NONE)
                               .score;

  const double t0 = NowSeconds();
  if (!problem_is_set) {
    backend->SetProblem(points, options.objective, options.num_threads);
  }
  internal::AttemptsCost cost;
  const Attempt attempt = internal::SolveAttempts(
      options, problem, initial_local, start_time_s, &cost);
  summary->attempts = cost.attempts;
  summary->point_iterations = cost.point_iterations;
  summary->solve_time_s = NowSeconds() - t0;
  summary->start_layer = attempt.start_layer;
  summary->trace = GlobalTrace(attempt, anchor);
  summary->iterations_per_layer = attempt.schedule.iterations_per_layer;
  summary->num_iterations = static_cast<int>(attempt.schedule.trace.size());
  if (attempt.schedule.termination_type == TerminationType::FAILURE) {
    return Fail(attempt.schedule.message, summary);
  }
  ReportSolution(problem, attempt, summary);
  Judge(options, attempt, summary);
}

// RegisterPrepared after preparing `input` (prepared_input.h): the one path
// of both Register entry points. `buffer`: memory for the input's range
// filter (see SampleInput), or null.
void RegisterOnMap(const RegistrationOptions& options,
                   const LayeredGrid& reference_map,
                   const PointCloud& input,
                   const Isometry3d& initial_reference_from_input,
                   double start_time_s,
                   RegistrationSummary* summary,
                   PointCloud* buffer = nullptr) {
  const std::unique_ptr<Backend> backend =
      CheckedBackend(options, reference_map, summary);
  if (!backend) return;
  PreparedInput prepared;
  internal::FilterSampleAndCentre(
      options.range_filter, options.sampling, input, &prepared, buffer);
  RegisterPrepared(options,
                   reference_map,
                   backend.get(),
                   prepared,
                   initial_reference_from_input,
                   start_time_s,
                   summary);
}

// What every Register entry point does around its work: the summary
// reset, the options checked (FAILURE naming the problem), work(start)
// when they are valid, and the total time.
template <typename Work>
void RegisterFrame(const RegistrationOptions& options,
                   RegistrationSummary* summary,
                   const Work& work) {
  CHECK(summary != nullptr);
  *summary = RegistrationSummary();
  const double start = NowSeconds();
  std::string error;
  if (!options.IsValid(&error)) {
    Fail(error, summary);
  } else {
    work(start);
  }
  summary->total_time_s = NowSeconds() - start;
}

}  // namespace

void Register(const RegistrationOptions& options,
              const LayeredGrid& reference_map,
              const PointCloud& input,
              const Isometry3d& initial_reference_from_input,
              RegistrationSummary* summary) {
  RegisterFrame(options, summary, [&](double start) {
    RegisterOnMap(options,
                  reference_map,
                  input,
                  initial_reference_from_input,
                  start,
                  summary);
  });
}

void Register(const RegistrationOptions& options,
              const LayeredGrid& reference_map,
              const PreparedInput& input,
              const Isometry3d& initial_reference_from_input,
              RegistrationSummary* summary) {
  RegisterFrame(options, summary, [&](double start) {
    if (const std::unique_ptr<Backend> backend =
            CheckedBackend(options, reference_map, summary)) {
      RegisterPrepared(options,
                       reference_map,
                       backend.get(),
                       input,
                       initial_reference_from_input,
                       start,
                       summary);
    }
  });
}

void Register(const RegistrationOptions& options,
              const PointCloud& reference,
              const PointCloud& input,
              const Isometry3d& initial_reference_from_input,
              RegistrationSummary* summary) {
  RegisterFrame(options, summary, [&](double start) {
    // The filtered reference, then the filtered input (RegisterOnMap's
    // buffer): reserved for the larger cloud, so the input's copy lands on
    // the pages the reference's touched (reserving touches none).
    PointCloud filtered;
    filtered.Reserve(std::max(reference.size(), input.size()));
    LayeredGrid map;
    std::string error;
    if (!internal::FilterReference(
            options.range_filter, reference, &filtered, &error) ||
        !LayeredGrid::Build(
            options.grid, filtered, options.num_threads, &map, &error)) {
      Fail("reference map: " + error, summary);
      return;
    }
    summary->map_time_s = NowSeconds() - start;
    RegisterOnMap(options,
                  map,
                  input,
                  initial_reference_from_input,
                  start,
                  summary,
                  &filtered);
  });
}

PreparedRegistration::PreparedRegistration(const RegistrationOptions& options,
                                           const PreparedInput& input)
    : options_(options), input_(input) {
  if (!options_.IsValid(&options_error_)) return;
  backend_ = CreateBackend(options_.backend, &backend_error_);
  if (backend_ != nullptr && input_.ok()) {
    backend_->SetProblem(
        input_.points, options_.objective, options_.num_threads);
  }
}

PreparedRegistration::~PreparedRegistration() = default;

void PreparedRegistration::Register(
    const LayeredGrid& reference_map,
    const Isometry3d& initial_reference_from_input,
    RegistrationSummary* summary) {
  CHECK(summary != nullptr);
  *summary = RegistrationSummary();
  const double start = NowSeconds();
  std::string error;
  // Register's checks in Register's order: the options, the map, the
  // backend.
  if (!options_error_.empty()) {
    Fail(options_error_, summary);
  } else if (!internal::CheckMap(reference_map, &error)) {
    Fail(error, summary);
  } else if (backend_ == nullptr) {
    Fail(backend_error_, summary);
  } else {
    RegisterPrepared(options_,
                     reference_map,
                     backend_.get(),
                     input_,
                     initial_reference_from_input,
                     start,
                     summary,
                     /*problem_is_set=*/true);
  }
  summary->total_time_s = NowSeconds() - start;
}

}  // namespace mlndt
