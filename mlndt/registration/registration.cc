#include "mlndt/registration/registration.h"

#include <glog/logging.h>

#include <iomanip>
#include <memory>
#include <sstream>

#include "mlndt/common/check_option.h"
#include "mlndt/common/enum_strings.h"
#include "mlndt/common/pose.h"
#include "mlndt/common/timer.h"
#include "mlndt/cost/score.h"
#include "mlndt/registration/ndt_registration.h"

namespace mlndt {
namespace {

void Fail(const std::string& message, RegistrationSummary* summary) {
  summary->termination_type = TerminationType::FAILURE;
  summary->message = message;
  LOG(ERROR) << "mlndt::Register: " << message;
}

std::unique_ptr<Backend> CreateBackend(const RegistrationOptions& options,
                                       std::string* error) {
  switch (options.backend) {
    case BackendType::CERES:
      return std::make_unique<CeresBackend>(options.ceres);
    case BackendType::NEWTON:
      return std::make_unique<NewtonBackend>(options.newton);
    case BackendType::LEVENBERG_MARQUARDT:
      return std::make_unique<LevenbergMarquardtBackend>(
          options.levenberg_marquardt);
  }
  *error = "unknown backend";
  return nullptr;
}

// Checks the input and the initial guess and samples the input (Section
// 4.3), filling the sampling counts and time. False (summary FAILURE) when
// nothing usable is left.
bool SampleInput(const RegistrationOptions& options,
                 const PointCloud& input,
                 const Isometry3d& initial_reference_from_input,
                 PointCloud* sampled,
                 RegistrationSummary* summary) {
  std::string error;
  if (input.empty()) {
    error = "the input cloud is empty";
  } else if (!AllFinite(input)) {
    error = "the input cloud has non-finite points";
  } else if (!initial_reference_from_input.matrix().allFinite()) {
    error = "the initial guess is not finite";
  } else {
    const double t0 = NowSeconds();
    SamplingSummary sampling_summary;
    if (!SamplePoints(
            options.sampling, input, sampled, &sampling_summary, &error)) {
      error = "sampling: " + error;
    } else {
      summary->sampling_time_s = NowSeconds() - t0;
      summary->input_points = input.size();
      summary->sampled_points = sampled->size();
      if (sampled->empty()) error = "sampling kept no input points";
    }
  }
  if (error.empty()) return true;
  Fail(error, summary);
  return false;
}

// FAILURE when too few sampled points are matched at the solution.
void CheckMatchedFraction(const RegistrationOptions& options,
                          RegistrationSummary* summary) {
  const double matched_fraction = static_cast<double>(summary->matched_points) /
                                  static_cast<double>(summary->sampled_points);
  if (matched_fraction < options.min_matched_fraction) {
    std::ostringstream message;
    message << "only " << summary->matched_points << " of "
            << summary->sampled_points
            << " sampled points lie in an occupied cell at the solution "
               "(min_matched_fraction "
            << options.min_matched_fraction << ")";
    Fail(message.str(), summary);
  }
}

// The whole ML-NDT registration after the map exists; times are added to
// *summary.
void RegisterOnMap(const RegistrationOptions& options,
                   const LayeredGrid& reference_map,
                   const PointCloud& input,
                   const Isometry3d& initial_reference_from_input,
                   double start_time_s,
                   RegistrationSummary* summary) {
  std::string error;
  if (!options.IsValid(&error)) return Fail(error, summary);
  if (options.method != Method::MLNDT) {
    return Fail(
        "method NDT needs the reference cloud (it builds its own single grid); "
        "call the Register overload that takes the reference PointCloud",
        summary);
  }
  if (reference_map.empty()) return Fail("the reference map is empty", summary);
  std::unique_ptr<Backend> backend = CreateBackend(options, &error);
  if (!backend) return Fail(error, summary);
  PointCloud sampled;
  if (!SampleInput(
          options, input, initial_reference_from_input, &sampled, summary))
    return;

  // Registration process (Table 1).
  const Vector6d initial_xi =
      IsometryToPoseVector(initial_reference_from_input);
  Vector6d xi = initial_xi;
  const int n = reference_map.num_layers();
  const NdtLayer& last = reference_map.layer(n);
  summary->initial_reference_from_input_xi = initial_xi;
  summary->num_layers = n;
  summary->map_occupied_cells = 0;
  for (const LayerInfo& info : reference_map.layer_info()) {
    summary->map_occupied_cells += info.occupied_cells;
  }
  summary->map_bytes = reference_map.MemoryBytes();
  summary->start_layer = ResolveStartLayer(options.schedule, n);
  summary->initial_score = EvaluateScore(last,
                                         sampled.points(),
                                         xi,
                                         options.unmatched_policy,
                                         options.loss,
                                         options.loss_scale)
                               .score;
  const double t0 = NowSeconds();
  StageOptions stage;
  stage.unmatched_policy = options.unmatched_policy;
  stage.loss = options.loss;
  stage.loss_scale = options.loss_scale;
  stage.num_threads = options.num_threads;
  stage.start_time_s = start_time_s;
  ScheduleSummary schedule;
  RunLayerSchedule(options.schedule,
                   reference_map,
                   sampled.points(),
                   stage,
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
  if (!xi.allFinite())
    return Fail("the solver returned a non-finite pose", summary);

  // Results on the last layer at the solution.
  const ScoreEvaluation final = EvaluateScore(last,
                                              sampled.points(),
                                              xi,
                                              options.unmatched_policy,
                                              options.loss,
                                              options.loss_scale);
  summary->reference_from_input_xi = xi;
  summary->reference_from_input = PoseVectorToIsometry(xi);
  summary->final_score = final.score;
  summary->matched_points = final.matched;
  summary->unmatched_points = final.unmatched;
  summary->hessian = final.hessian;
  const Eigen::FullPivLU<Matrix6d> lu(final.hessian);
  summary->covariance =
      lu.isInvertible() ? Matrix6d(2.0 * lu.inverse()) : Matrix6d::Zero();
  summary->termination_type = schedule.termination_type;
  summary->message = schedule.message;
  CheckMatchedFraction(options, summary);
}

// The conventional NDT baseline (ndt_registration.h); options are valid.
void RegisterNdt(const RegistrationOptions& options,
                 const PointCloud& reference,
                 const PointCloud& input,
                 const Isometry3d& initial_reference_from_input,
                 double start_time_s,
                 RegistrationSummary* summary) {
  std::string error;
  NdtLayer grid;
  if (!internal::BuildNdtGrid(options, reference, &grid, &error)) {
    return Fail("reference map: " + error, summary);
  }
  summary->map_time_s = NowSeconds() - start_time_s;
  PointCloud sampled;
  if (!SampleInput(
          options, input, initial_reference_from_input, &sampled, summary))
    return;
  if (!internal::RegisterOnNdtGrid(
          options,
          grid,
          sampled.points(),
          IsometryToPoseVector(initial_reference_from_input),
          start_time_s,
          summary,
          &error)) {
    return Fail(error, summary);
  }
  CheckMatchedFraction(options, summary);
}

}  // namespace

LayeredGridOptions DefaultRegistrationGridOptions() {
  LayeredGridOptions options;
  options.finest_cell_size_m = 2.0;
  return options;
}

LayerScheduleOptions DefaultRegistrationScheduleOptions() {
  LayerScheduleOptions options;
  options.start_layer = 1;
  options.iterations_per_layer = 6;
  options.max_coarse_point_stride = 8;
  return options;
}

const char* MethodToString(Method method) {
  switch (method) {
    case Method::MLNDT:
      return "MLNDT";
    case Method::NDT:
      return "NDT";
  }
  return "UNKNOWN";
}

bool StringToMethod(std::string value, Method* result) {
  UpperCase(&value);
  if (value == "ML-NDT" || value == "ML_NDT") value = "MLNDT";
  MLNDT_STRING_TO_ENUM(MLNDT, Method);
  MLNDT_STRING_TO_ENUM(NDT, Method);
  return false;
}

bool NdtBaselineOptions::IsValid(std::string* error) const {
  MLNDT_OPTION_GE(cell_size_m, 0.0);
  MLNDT_OPTION_GT(outlier_ratio, 0.0);
  MLNDT_OPTION_LT(outlier_ratio, 1.0);
  MLNDT_OPTION_GE(max_iterations, 1);
  MLNDT_OPTION_GE(max_step_norm, 0.0);
  return true;
}

bool RegistrationOptions::IsValid(std::string* error) const {
  if (!ndt.IsValid(error) || !grid.IsValid(error) || !sampling.IsValid(error) ||
      !schedule.IsValid(error) || !ceres.IsValid(error) ||
      !newton.IsValid(error) || !levenberg_marquardt.IsValid(error)) {
    return false;
  }
  MLNDT_OPTION_GE(num_threads, 1);
  MLNDT_OPTION_GT(loss_scale, 0.0);
  MLNDT_OPTION_GE(min_matched_fraction, 0.0);
  MLNDT_OPTION_LE(min_matched_fraction, 1.0);
  return true;
}

void Register(const RegistrationOptions& options,
              const LayeredGrid& reference_map,
              const PointCloud& input,
              const Isometry3d& initial_reference_from_input,
              RegistrationSummary* summary) {
  CHECK(summary != nullptr);
  *summary = RegistrationSummary();
  summary->method = options.method;
  const double start = NowSeconds();
  RegisterOnMap(options,
                reference_map,
                input,
                initial_reference_from_input,
                start,
                summary);
  summary->total_time_s = NowSeconds() - start;
}

void Register(const RegistrationOptions& options,
              const PointCloud& reference,
              const PointCloud& input,
              const Isometry3d& initial_reference_from_input,
              RegistrationSummary* summary) {
  CHECK(summary != nullptr);
  *summary = RegistrationSummary();
  summary->method = options.method;
  const double start = NowSeconds();
  std::string error;
  LayeredGrid map;
  if (!options.IsValid(&error)) {
    Fail(error, summary);
  } else if (options.method == Method::NDT) {
    RegisterNdt(options,
                reference,
                input,
                initial_reference_from_input,
                start,
                summary);
  } else if (!LayeredGrid::Build(options.grid, reference, &map, &error)) {
    Fail("reference map: " + error, summary);
  } else {
    summary->map_time_s = NowSeconds() - start;
    RegisterOnMap(
        options, map, input, initial_reference_from_input, start, summary);
  }
  summary->total_time_s = NowSeconds() - start;
}

std::string RegistrationSummary::BriefReport() const {
  std::ostringstream out;
  out << (method == Method::NDT ? "NDT" : "ML-NDT")
      << " registration: " << TerminationTypeToString(termination_type) << ", "
      << num_iterations << " iterations, score " << initial_score << " -> "
      << final_score << ", " << std::fixed << std::setprecision(1)
      << total_time_s * 1e3 << " ms";
  return out.str();
}

std::string RegistrationSummary::FullReport() const {
  std::ostringstream out;
  out << BriefReport() << "\n";
  out << "  message:        " << message << "\n";
  out << std::setprecision(4) << std::fixed;
  const Vector6d& xi = reference_from_input_xi;
  out << "  pose xi:        t = (" << xi(0) << ", " << xi(1) << ", " << xi(2)
      << ") m, "
      << "(alpha, beta, gamma) = (" << xi(3) * kRadToDeg << ", "
      << xi(4) * kRadToDeg << ", " << xi(5) * kRadToDeg << ") deg\n";
  if (method == Method::NDT) {
    out << "  grid:           one grid of " << ndt_cell_size_m
        << " m cells, iterations " << num_iterations;
  } else {
    out << "  layers:         start " << start_layer << " of " << num_layers
        << ", iterations";
    for (size_t i = 0; i < iterations_per_layer.size(); ++i) {
      out << " L" << i + 1 << "=" << iterations_per_layer[i];
    }
  }
  out << "\n  points:         " << input_points << " input, " << sampled_points
      << " sampled, " << matched_points << " matched, " << unmatched_points
      << " unmatched\n";
  out << std::setprecision(2) << "  time [ms]:      map " << map_time_s * 1e3
      << ", sampling " << sampling_time_s * 1e3 << ", solve "
      << solve_time_s * 1e3 << ", total " << total_time_s * 1e3 << "\n";
  if (map_occupied_cells > 0) {
    out << std::setprecision(3) << "  map memory:     " << map_bytes / 1e6
        << " MB, " << map_occupied_cells << " occupied cells, "
        << std::setprecision(0)
        << static_cast<double>(map_bytes) / map_occupied_cells
        << " bytes per cell\n";
  }
  out << std::setprecision(4) << "  sigma (cov):    t = ("
      << std::sqrt(covariance(0, 0)) << ", " << std::sqrt(covariance(1, 1))
      << ", " << std::sqrt(covariance(2, 2)) << ") m, angles = ("
      << std::sqrt(covariance(3, 3)) * kRadToDeg << ", "
      << std::sqrt(covariance(4, 4)) * kRadToDeg << ", "
      << std::sqrt(covariance(5, 5)) * kRadToDeg << ") deg\n";
  return out.str();
}

}  // namespace mlndt
