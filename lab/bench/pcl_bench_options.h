#pragma once

// The settings of PCL's registrations in mlndt_bench
// (lab/bench/pcl_methods.h says what each does; mlndt_bench's --pcl_*
// flags set them).

#include <string>

namespace mlndt {

struct PclBenchOptions {
  double leaf_size_m = 0.1;  // pcl_ndt: VoxelGrid leaf for both clouds.
  // pcl_ndt.
  double ndt_resolution_m = 1.0;
  double ndt_step_size_m = 1.0;  // More-Thuente maximum step (PCL: 0.1).
  // Stops when the squared translation of a step is <= this [m^2].
  double ndt_transformation_epsilon = 1e-4;
  int ndt_max_iterations = 35;
  // pcl_gicp, set up as the peer harness of issue 45 (the proxy of the
  // fastest peers): a 0.25 m VoxelGrid on both clouds, correspondences
  // within 1 m, PCL 1.13's other defaults.
  double gicp_leaf_size_m = 0.25;
  double gicp_max_correspondence_distance_m = 1.0;
  int gicp_max_iterations = 200;

  // The ranges of PclBenchOptionsTable (bench_option_tables.h): leaf,
  // resolution, step size and distance > 0, epsilon >= 0, caps >= 1; else
  // false with *error naming the field.
  bool IsValid(std::string* error) const;
};

}  // namespace mlndt
