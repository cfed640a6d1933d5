#include "mlndt/registration/internal/registration_steps.h"

#include <glog/logging.h>

#include <sstream>

#include "mlndt/common/rigid_transform.h"
#include "mlndt/common/timer.h"

namespace mlndt {
namespace internal {

void Fail(const char* entry_point,
          const std::string& message,
          RegistrationSummary* summary) {
  summary->termination_type = TerminationType::FAILURE;
  summary->message = message;
  // The caller reports the failure (summary->message); a log line here
  // would print an error for every expected one (--v=1 shows them).
  VLOG(1) << entry_point << ": " << message;
}

bool SampleInput(const RangeFilterOptions& range_filter,
                 const SamplingOptions& options,
                 const PointCloud& input,
                 const Isometry3d& initial_reference_from_input,
                 PointCloud* sampled,
                 RegistrationSummary* summary,
                 std::string* error,
                 PointCloud* buffer) {
  return CheckInput(input, error) &&
         CheckInitialGuess(initial_reference_from_input, error) &&
         FilterAndSample(
             range_filter, options, input, sampled, summary, error, buffer);
}

bool CheckInput(const PointCloud& input, std::string* error) {
  if (input.empty()) {
    *error = "the input cloud is empty";
    return false;
  }
  if (!AllFinite(input)) {
    *error = "the input cloud has non-finite points";
    return false;
  }
  return true;
}

bool CheckInitialGuess(const Isometry3d& initial_reference_from_input,
                       std::string* error) {
  if (!initial_reference_from_input.matrix().allFinite()) {
    *error = "the initial guess is not finite";
    return false;
  }
  // The one rigidity check (rigid_transform.h); the solver parameterises the
  // guess by Eq. (11)'s angles, which re-orthonormalises what passes.
  Isometry3d rigid;
  std::string problem;
  if (!ToRigidTransform(
          initial_reference_from_input.matrix(), &rigid, &problem)) {
    *error = "the initial guess is not a rigid transform: " + problem;
    return false;
  }
  return true;
}

bool FilterAndSample(const RangeFilterOptions& range_filter,
                     const SamplingOptions& options,
                     const PointCloud& input,
                     PointCloud* sampled,
                     RegistrationSummary* summary,
                     std::string* error,
                     PointCloud* buffer) {
  const double t0 = NowSeconds();
  RangeFilterSummary filter_summary;
  PointCloud own_buffer;
  PointCloud& kept = buffer != nullptr ? *buffer : own_buffer;
  FilterByRange(range_filter, input, &kept, &filter_summary);
  summary->input_points = input.size();
  summary->range_filtered_points = input.size() - kept.size();
  if (kept.empty()) {
    *error = "the range filter dropped every input point: " +
             DescribeDroppedPoints(range_filter, filter_summary);
    return false;
  }
  SamplingSummary sampling_summary;
  if (!SamplePoints(options, kept, sampled, &sampling_summary, error)) {
    *error = "sampling: " + *error;
    return false;
  }
  summary->sampling_time_s = NowSeconds() - t0;
  summary->sampled_points = sampled->size();
  if (sampled->empty()) {
    *error = "sampling kept no input points";
    // GBS drops cells with too few points: with a tiny cell, every cell.
    if (options.method == SamplingMethod::GBS &&
        sampling_summary.dropped_sparse_cells > 0) {
      std::ostringstream why;
      why << ": all " << sampling_summary.occupied_cells
          << " cells of gbs_cell_size_m = " << options.gbs_cell_size_m
          << " m hold fewer than gbs_min_points_per_cell = "
          << options.gbs_min_points_per_cell
          << " points (a larger cell, e.g. the default, or fewer points per "
             "cell)";
      *error += why.str();
    }
    return false;
  }
  return true;
}

bool FilterReference(const RangeFilterOptions& range_filter,
                     const PointCloud& reference,
                     PointCloud* filtered,
                     std::string* error) {
  RangeFilterSummary summary;
  FilterByRange(range_filter, reference, filtered, &summary);
  if (filtered->empty() && !reference.empty()) {
    *error = "the range filter dropped every reference point: " +
             DescribeDroppedPoints(range_filter, summary);
    return false;
  }
  return true;
}

bool CheckMap(const LayeredGrid& map, std::string* error) {
  if (map.empty()) {
    *error = "the reference map is empty";
    return false;
  }
  if (map.layer(map.num_layers()).cells().empty()) {
    *error = "the reference map has no occupied cell on its last layer";
    return false;
  }
  return true;
}

void DescribeMap(const LayeredGrid& map, RegistrationSummary* summary) {
  summary->num_layers = map.num_layers();
  summary->finest_cell_size_m = map.layer(map.num_layers()).cell_size();
  summary->map_occupied_cells = 0;
  for (const LayerInfo& info : map.layer_info()) {
    summary->map_occupied_cells += info.occupied_cells;
  }
  summary->map_bytes = map.MemoryBytes();
}

std::string CheckMatchedFraction(double min_fraction,
                                 const RegistrationSummary& summary) {
  const double matched_fraction = static_cast<double>(summary.matched_points) /
                                  static_cast<double>(summary.sampled_points);
  if (matched_fraction >= min_fraction) return "";
  std::ostringstream message;
  message << "only " << summary.matched_points << " of "
          << summary.sampled_points
          << " sampled points lie in an occupied cell at the solution "
             "(min_matched_fraction "
          << min_fraction << ")";
  return message.str();
}

}  // namespace internal
}  // namespace mlndt
