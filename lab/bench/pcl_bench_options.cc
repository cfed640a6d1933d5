#include "lab/bench/pcl_bench_options.h"

#include <cmath>

namespace mlndt {
namespace {

bool Positive(double value, const char* flag, std::string* error) {
  if (std::isfinite(value) && value > 0.0) return true;
  *error = std::string("--") + flag + " must be > 0";
  return false;
}

}  // namespace

bool PclBenchOptions::IsValid(std::string* error) const {
  if (!Positive(leaf_size_m, "pcl_leaf_size", error) ||
      !Positive(ndt_resolution_m, "pcl_resolution", error) ||
      !Positive(ndt_step_size_m, "pcl_step_size", error) ||
      !Positive(gicp_max_correspondence_distance_m,
                "pcl_gicp_max_correspondence_distance",
                error)) {
    return false;
  }
  if (!std::isfinite(ndt_transformation_epsilon) ||
      ndt_transformation_epsilon < 0.0) {
    *error = "--pcl_transformation_epsilon must be >= 0";
    return false;
  }
  if (ndt_max_iterations < 1 || gicp_max_iterations < 1) {
    *error = "--pcl_max_iterations and --pcl_gicp_max_iterations must be >= 1";
    return false;
  }
  return true;
}

}  // namespace mlndt
