#include "tools/common/json_output.h"

#include <cmath>

#include "mlndt/common/atomic_file.h"
#include "mlndt/common/pose.h"
#include "tools/common/tool_utils.h"

namespace mlndt {
namespace tools {
namespace {

Json Vector3Json(double x, double y, double z) {
  return Json::array({Number(x), Number(y), Number(z)});
}

// A 6x6 matrix as 6 rows of 6 numbers; infinite entries become null.
Json Matrix6Json(const Matrix6d& m) {
  Json rows = Json::array();
  for (int r = 0; r < 6; ++r) {
    Json row = Json::array();
    for (int c = 0; c < 6; ++c) row.push_back(Number(m(r, c)));
    rows.push_back(row);
  }
  return rows;
}

// The covariance of xi = (t [m], angles [rad]) with the angles in degrees:
// S C S with S = diag(1, 1, 1, k, k, k), k = 180 / pi.
Matrix6d CovarianceInDegrees(const Matrix6d& covariance) {
  Vector6d scale;
  scale << 1.0, 1.0, 1.0, kRadToDeg, kRadToDeg, kRadToDeg;
  return scale.asDiagonal() * covariance * scale.asDiagonal();
}

Json TraceJson(const RegistrationSummary& summary) {
  Json trace = Json::array();
  for (const IterationRecord& r : summary.trace) {
    trace.push_back({{"iteration", r.iteration},
                     {"layer", r.layer},
                     {"score", Number(r.score)},
                     {"step_norm", Number(r.step_norm)},
                     {"step_is_successful", r.step_is_successful},
                     {"xi", PoseVectorJson(r.reference_from_input_xi)},
                     {"time_ms", Number(r.time_s * 1e3)}});
  }
  return trace;
}

}  // namespace

Json ToolJson(const std::string& tool) {
  return {{"schema_version", kJsonSchemaVersion},
          {"tool", tool},
          {"version", MLNDT_VERSION},
          {"command", CommandLine()}};
}

Json Number(double value) {
  if (!std::isfinite(value)) return nullptr;
  return value;
}

double WrapDegrees(double degrees) {
  if (!std::isfinite(degrees)) return degrees;
  double wrapped = std::fmod(degrees, 360.0);
  if (wrapped <= -180.0) wrapped += 360.0;
  if (wrapped > 180.0) wrapped -= 360.0;
  return wrapped;
}

Json MatrixJson(const Isometry3d& transform) {
  Json rows = Json::array();
  for (int r = 0; r < 4; ++r) {
    Json row = Json::array();
    for (int c = 0; c < 4; ++c) row.push_back(Number(transform.matrix()(r, c)));
    rows.push_back(row);
  }
  return rows;
}

Json PoseVectorJson(const Vector6d& xi) {
  return {{"translation_m", Vector3Json(xi(0), xi(1), xi(2))},
          {"rotation_deg",
           Vector3Json(WrapDegrees(xi(3) * kRadToDeg),
                       WrapDegrees(xi(4) * kRadToDeg),
                       WrapDegrees(xi(5) * kRadToDeg))}};
}

Json PoseJson(const Isometry3d& transform) {
  return PoseVectorJson(IsometryToPoseVector(transform));
}

Json StatsJson(const Stats& stats) {
  return {{"count", stats.count},
          {"mean", Number(stats.mean)},
          {"median", Number(stats.median)},
          {"min", Number(stats.min)},
          {"max", Number(stats.max)},
          {"std", Number(stats.std)},
          {"p95", Number(stats.p95)}};
}

Json RegistrationTimeJson(const RegistrationSummary& summary) {
  return {{"total", Number(summary.total_time_s * 1e3)},
          {"map", Number(summary.map_time_s * 1e3)},
          {"sampling", Number(summary.sampling_time_s * 1e3)},
          {"solve", Number(summary.solve_time_s * 1e3)}};
}

Json RegistrationSummaryJson(const RegistrationSummary& summary,
                             bool with_trace) {
  Json degenerate = Json::array();
  for (const Vector6d& d : summary.constraints.degenerate_directions) {
    Json direction = Json::array();
    for (int k = 0; k < 6; ++k) direction.push_back(Number(d(k)));
    degenerate.push_back(direction);
  }
  Json json = {
      {"algorithm", summary.algorithm},
      {"termination", TerminationTypeToString(summary.termination_type)},
      {"usable", summary.IsSolutionUsable()},
      {"message", summary.message},
      {"reference_from_input", MatrixJson(summary.reference_from_input)},
      {"xi", PoseVectorJson(summary.reference_from_input_xi)},
      {"initial_xi", PoseVectorJson(summary.initial_reference_from_input_xi)},
      {"iterations", summary.num_iterations},
      {"iterations_per_layer", summary.iterations_per_layer},
      {"attempts", summary.attempts},
      {"start_layer", summary.start_layer},
      {"num_layers", summary.num_layers},
      {"finest_cell_size_m", Number(summary.finest_cell_size_m)},
      {"score",
       {{"initial", Number(summary.initial_score)},
        {"final", Number(summary.final_score)}}},
      {"points",
       {{"input", summary.input_points},
        {"range_filtered", summary.range_filtered_points},
        {"sampled", summary.sampled_points},
        {"matched", summary.matched_points},
        {"unmatched", summary.unmatched_points}}},
      {"quality",
       {{"points", summary.quality.points},
        {"own_cell_fraction", Number(summary.quality.own_cell_fraction)},
        {"inlier_fraction", Number(summary.quality.inlier_fraction)},
        {"mean_score", Number(summary.quality.mean_score)},
        {"median_distance", Number(summary.quality.median_distance)},
        // Deprecated: the same value under its first, wrong name (it is a
        // Mahalanobis distance, not metres); kept for existing readers.
        {"median_distance_m", Number(summary.quality.median_distance)},
        {"constraint_ratio", Number(summary.constraints.constraint_ratio)},
        {"flatness", Number(summary.constraints.flatness)},
        {"probe_evidence", Number(summary.constraints.probe_evidence)},
        {"degenerate_directions", degenerate}}},
      {"map",
       {{"occupied_cells", summary.map_occupied_cells},
        {"memory_bytes", summary.map_bytes}}},
      {"time_ms", RegistrationTimeJson(summary)},
      {"covariance_m_deg",
       {{"order",
         {"tx_m", "ty_m", "tz_m", "alpha_deg", "beta_deg", "gamma_deg"}},
        {"matrix", Matrix6Json(CovarianceInDegrees(summary.covariance))}}}};
  if (with_trace) json["trace"] = TraceJson(summary);
  return json;
}

std::string JsonText(const Json& json) {
  return json.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

bool WriteJsonFile(const std::string& path,
                   const Json& json,
                   std::string* error) {
  return WriteFileAtomically(path, JsonText(json), error);
}

}  // namespace tools
}  // namespace mlndt
