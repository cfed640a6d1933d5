#include "mlndt/registration/internal/registration_steps.h"

#include <glog/logging.h>

#include <sstream>

#include "mlndt/common/timer.h"

namespace mlndt {
namespace internal {

void Fail(const char* entry_point,
          const std::string& message,
          RegistrationSummary* summary) {
  summary->termination_type = TerminationType::FAILURE;
  summary->message = message;
  LOG(ERROR) << entry_point << ": " << message;
}

bool SampleInput(const RangeFilterOptions& range_filter,
                 const SamplingOptions& options,
                 const PointCloud& input,
                 const Isometry3d& initial_reference_from_input,
                 PointCloud* sampled,
                 RegistrationSummary* summary,
                 std::string* error) {
  if (input.empty()) {
    *error = "the input cloud is empty";
    return false;
  }
  if (!AllFinite(input)) {
    *error = "the input cloud has non-finite points";
    return false;
  }
  if (!initial_reference_from_input.matrix().allFinite()) {
    *error = "the initial guess is not finite";
    return false;
  }
  const Eigen::Matrix3d r = initial_reference_from_input.linear();
  const double orthogonality =
      (r.transpose() * r - Eigen::Matrix3d::Identity()).norm();
  const Eigen::RowVector4d last_row =
      initial_reference_from_input.matrix().row(3);
  if (orthogonality > 1e-6 || r.determinant() < 0.0 ||
      (last_row - Eigen::RowVector4d(0, 0, 0, 1)).norm() > 1e-12) {
    std::ostringstream message;
    message << "the initial guess is not a rigid transform (|R^T R - I| = "
            << orthogonality << ", det R = " << r.determinant()
            << "): give a rotation, not a reflection or a scaled matrix";
    *error = message.str();
    return false;
  }
  const double t0 = NowSeconds();
  RangeFilterSummary filter_summary;
  const PointCloud kept = FilterByRange(range_filter, input, &filter_summary);
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
    return false;
  }
  return true;
}

bool FilterReference(const RangeFilterOptions& range_filter,
                     const PointCloud& reference,
                     PointCloud* filtered,
                     std::string* error) {
  RangeFilterSummary summary;
  *filtered = FilterByRange(range_filter, reference, &summary);
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
