#include "tools/cli/json_output.h"

#include <cmath>

#include "mlndt/common/atomic_file.h"
#include "mlndt/common/pose.h"
#include "mlndt/common/result_table.h"
#include "tools/cli/result_json.h"
#include "tools/cli/tool_utils.h"

namespace mlndt {
namespace tools {
namespace {

Json Vector3Json(double x, double y, double z) {
  return Json::array({Number(x), Number(y), Number(z)});
}

// A 4x4 transform as 4 rows of 4 numbers (row-major).
Json MatrixJson(const Isometry3d& transform) {
  Json rows = Json::array();
  for (int r = 0; r < 4; ++r) {
    Json row = Json::array();
    for (int c = 0; c < 4; ++c) row.push_back(Number(transform.matrix()(r, c)));
    rows.push_back(row);
  }
  return rows;
}

// An angle [deg] wrapped to (-180, 180].
double WrapDegrees(double degrees) {
  if (!std::isfinite(degrees)) return degrees;
  double wrapped = std::fmod(degrees, 360.0);
  if (wrapped <= -180.0) wrapped += 360.0;
  if (wrapped > 180.0) wrapped -= 360.0;
  return wrapped;
}

// A pose vector xi = (t [m], Euler angles [rad], ML-NDT Eq. 11) as
// {"translation_m": [x, y, z], "rotation_deg": [alpha, beta, gamma]}, the
// angles wrapped to (-180, 180] (R = Rx(alpha) Ry(beta) Rz(gamma)).
Json PoseVectorJson(const Vector6d& xi) {
  return {{"translation_m", Vector3Json(xi(0), xi(1), xi(2))},
          {"rotation_deg",
           Vector3Json(WrapDegrees(xi(3) * kRadToDeg),
                       WrapDegrees(xi(4) * kRadToDeg),
                       WrapDegrees(xi(5) * kRadToDeg))}};
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

Json KittiLengthsJson(const std::vector<KittiLengthErrors>& lengths) {
  Json json = Json::array();
  for (const KittiLengthErrors& l : lengths) {
    json.push_back(
        {{"length_m", Number(l.length_m)},
         {"segments", l.num_segments},
         {"translation_error_percent", Number(l.translation_error_percent)},
         {"rotation_error_deg_per_m", Number(l.rotation_error_deg_per_m)}});
  }
  return json;
}

Json RegistrationSummaryJson(const RegistrationSummary& summary,
                             bool with_trace) {
  std::vector<std::string> skip;
  if (!with_trace) skip.push_back("trace");
  return ResultJsonOf(RegistrationSummaryTable(), summary, skip);
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
