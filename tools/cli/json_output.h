#pragma once

// The tools' JSON output, built with nlohmann::json in one place: the
// header every file starts with, poses, statistics, timings and a
// RegistrationSummary. Conventions (docs/json_schema.md):
//  - every file holds "schema_version": kJsonSchemaVersion, "tool" and
//    "version" (ToolJson);
//  - units are in the key names (_m, _deg, _ms, _bytes); angles are in
//    degrees (poses wrapped to (-180, 180]), except in the objects made
//    from a result table (result_json.h), which keep the struct's units;
//  - timings are one object "time_ms": {"total": ..., <stage>: ...}; a
//    distribution of times over many runs is "time_ms_stats";
//  - numbers are written with 17 significant digits (they round-trip);
//    NaN and infinities are written as null.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "lab/eval/kitti_segment_errors.h"
#include "lab/eval/statistics.h"
#include "mlndt/common/types.h"
#include "mlndt/registration/registration_summary.h"

namespace mlndt {
namespace tools {

// Keys keep the order they are added in.
using Json = nlohmann::ordered_json;

// 2: the registration object is made from RegistrationSummaryTable()
// (keys renamed to the C++ fields; docs/json_schema.md).
constexpr int kJsonSchemaVersion = 2;

// {"schema_version": 1, "tool": tool, "version": "<PROJECT_VERSION>",
//  "command": the command line}.
Json ToolJson(const std::string& tool);

// `value`, or null when it is not finite.
Json Number(double value);

// The same for a transform (IsometryToPoseVector).
Json PoseJson(const Isometry3d& transform);

// {"count", "mean", "median", "min", "max", "std", "p95"}.
Json StatsJson(const Stats& stats);

// The KITTI devkit's errors per segment length, one object each:
// {"length_m", "segments", "translation_error_percent",
//  "rotation_error_deg_per_m"} (mlndt_eval's and mlndt_odometry's JSON).
Json KittiLengthsJson(const std::vector<KittiLengthErrors>& lengths);

// The one JSON form of a registration's result (docs/json_schema.md,
// "registration"): ResultJson of RegistrationSummaryTable(), every field of
// the summary under its C++ name and in its unit (s, m, rad); the
// per-iteration trace only `with_trace`.
Json RegistrationSummaryJson(const RegistrationSummary& summary,
                             bool with_trace);

// The text WriteJsonFile writes: json.dump(2) and a newline (invalid UTF-8
// replaced).
std::string JsonText(const Json& json);

// Writes JsonText(json) to `path` atomically (WriteFileAtomically); false
// with *error when it cannot.
bool WriteJsonFile(const std::string& path,
                   const Json& json,
                   std::string* error);

}  // namespace tools
}  // namespace mlndt
