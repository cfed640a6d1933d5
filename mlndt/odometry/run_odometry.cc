#include "mlndt/odometry/run_odometry.h"

#include <glog/logging.h>

#include <cstdio>

namespace mlndt {
namespace {

// The progress line of a scan:
// "CONVERGENCE (prediction used), layer 4, +-0.10 m 2.0 deg, 443 ms".
std::string StatusLine(const OdometryResult& r) {
  char line[160];
  std::snprintf(line,
                sizeof(line),
                "%s%s, layer %d, +-%.2f m %.1f deg, %.0f ms",
                TerminationTypeToString(r.termination_type),
                r.fallback ? " (prediction used)" : "",
                r.registration.start_layer,
                r.uncertainty.translation_m,
                r.uncertainty.rotation_deg,
                r.total_time_s * 1e3);
  return line;
}

}  // namespace

bool RunOdometry(const OdometryOptions& options,
                 size_t num_scans,
                 const OdometryScanLoader& load_scan,
                 ProgressCallback* progress,
                 std::vector<OdometryResult>* results,
                 OdometrySummary* summary,
                 std::string* error) {
  CHECK(results != nullptr);
  CHECK(summary != nullptr);
  CHECK(error != nullptr);
  CHECK(load_scan);
  results->clear();
  *summary = OdometrySummary();
  if (!options.IsValid(error)) return false;
  Odometry odometry(options);
  PointCloud cloud;
  std::vector<double> point_times_s;
  results->reserve(num_scans);
  for (size_t k = 0; k < num_scans; ++k) {
    double stamp_s = 0.0;
    if (!load_scan(k, &cloud, &point_times_s, &stamp_s, error)) return false;
    OdometryResult result;
    if (!odometry.Process({stamp_s, &cloud, &point_times_s}, &result, error)) {
      return false;
    }
    for (const BridgedScan& bridged : result.bridged) {
      OdometryResult& earlier = (*results)[bridged.index];
      earlier.world_from_sensor = bridged.world_from_sensor;
      earlier.interpolated = true;
    }
    results->push_back(result);
    summary->Add(result);
    ReportProgress(progress, {k, k + 1, num_scans, StatusLine(result)});
  }
  return true;
}

}  // namespace mlndt
