#pragma once

// The registration flags shared by the tools: every MatcherOptions field a
// user tunes, with the library's defaults (or the paper's, --preset=paper).
// The flags are defined in registration_flags.cc; a tool that calls
// MatcherOptionsFromFlags gets them (and shows them in --help).

#include <gflags/gflags.h>

#include <string>

#include "lab/runs/matcher.h"

// clang-format off
DECLARE_string(preset);
DECLARE_string(method);
DECLARE_double(ndt_cell_size);
DECLARE_double(ndt_outlier_ratio);
DECLARE_string(ndt_neighbors);
DECLARE_int32(ndt_max_iterations);
DECLARE_double(ndt_max_step);
DECLARE_string(backend);
DECLARE_string(sampling);
DECLARE_double(random_fraction);
DECLARE_double(gbs_cell_size);
DECLARE_int32(start_layer);
DECLARE_int32(num_layers);
DECLARE_int32(division_constant);
DECLARE_double(finest_cell_size);
DECLARE_int32(min_points_per_cell);
DECLARE_double(min_eigenvalue);
DECLARE_double(min_eigenvalue_ratio);
DECLARE_string(coarse_weighting);
DECLARE_double(min_range);
DECLARE_double(max_range);
DECLARE_double(saturated_range_fraction);
DECLARE_int32(iterations_per_layer);
DECLARE_int32(max_iterations);
DECLARE_double(step_tolerance);
DECLARE_double(coarse_step_tolerance);
DECLARE_int32(max_coarse_point_stride);
DECLARE_string(unmatched);
DECLARE_string(loss);
DECLARE_double(loss_scale);
DECLARE_string(linear_solver);
DECLARE_string(trust_region);
DECLARE_int32(threads);
DECLARE_uint64(seed);
DECLARE_string(initial_uncertainty);
DECLARE_bool(quality_check);
DECLARE_double(min_inlier_fraction);
DECLARE_double(max_mean_score);
DECLARE_double(inlier_gate);
DECLARE_double(min_constraint_ratio);
DECLARE_string(retry_yaw_seeds);
// clang-format on

namespace mlndt {
namespace tools {

// Fills *options from --preset and the flags given on the command line;
// false with *error naming the flag for a bad value or a combination that
// would be silently ignored (e.g. --backend with --method=ndt).
bool MatcherOptionsFromFlags(MatcherOptions* options, std::string* error);

// The range filter of --min_range, --max_range and
// --saturated_range_fraction; false with *error naming the flag.
bool RangeFilterOptionsFromFlags(RangeFilterOptions* filter,
                                 std::string* error);

// The registration options of --preset and the ML-NDT flags (ML-NDT only;
// false with *error for --method=ndt).
bool RegistrationOptionsFromFlags(RegistrationOptions* options,
                                  std::string* error);

}  // namespace tools
}  // namespace mlndt
