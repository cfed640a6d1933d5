#include "mlndt/odometry/run_odometry.h"

#include <glog/logging.h>

namespace mlndt {

bool RunOdometry(const OdometryOptions& options,
                 size_t num_scans,
                 const OdometryScanLoader& load_scan,
                 const OdometryCallback& on_result,
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
    if (on_result) on_result(results->back());
  }
  return true;
}

}  // namespace mlndt
