#include "mlndt/registration/prepared_input.h"

#include <glog/logging.h>

#include <cmath>

#include "mlndt/registration/internal/registration_steps.h"

namespace mlndt {
namespace internal {
namespace {

// The sampled points relative to their centroid, that centroid and their
// RMS distance from it.
void Centre(const PointCloud& sampled, PreparedInput* prepared) {
  Eigen::Vector3d& centre = prepared->centre;
  centre = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : sampled.points()) centre += p;
  centre /= static_cast<double>(sampled.size());
  std::vector<Eigen::Vector3d>& points = prepared->points;
  points.clear();
  points.reserve(sampled.size());
  double squares = 0.0;
  for (const Eigen::Vector3d& p : sampled.points()) {
    points.push_back(p - centre);
    squares += points.back().squaredNorm();
  }
  prepared->rms_range_m =
      std::sqrt(squares / static_cast<double>(sampled.size()));
}

}  // namespace

bool FilterSampleAndCentre(const RangeFilterOptions& range_filter,
                           const SamplingOptions& options,
                           const PointCloud& input,
                           PreparedInput* prepared,
                           PointCloud* buffer) {
  CHECK(prepared != nullptr);
  *prepared = PreparedInput();
  if (!CheckInput(input, &prepared->input_error)) return false;
  RegistrationSummary counts;
  PointCloud sampled;
  std::string error;
  const bool sampled_ok = FilterAndSample(
      range_filter, options, input, &sampled, &counts, &error, buffer);
  prepared->input_points = counts.input_points;
  prepared->range_filtered_points = counts.range_filtered_points;
  prepared->sampled_points = counts.sampled_points;
  prepared->sampling_time_s = counts.sampling_time_s;
  if (!sampled_ok) {
    prepared->sampling_error = error;
    return false;
  }
  Centre(sampled, prepared);
  return true;
}

}  // namespace internal

bool PrepareInput(const RegistrationOptions& options,
                  const PointCloud& input,
                  PreparedInput* prepared) {
  CHECK(prepared != nullptr);
  std::string error;
  if (!options.IsValid(&error)) {
    *prepared = PreparedInput();
    prepared->input_error = "prepared with invalid options: " + error;
    return false;
  }
  return internal::FilterSampleAndCentre(
      options.range_filter, options.sampling, input, prepared);
}

}  // namespace mlndt
