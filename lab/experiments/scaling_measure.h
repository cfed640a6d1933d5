#pragma once

// One point of mlndt_scaling (the tool parses --sizes: ParseSizes in
// tools/cli/list_flags.h): registering a random subset of N points of a
// merged cloud onto another, independently drawn one, and what it measures.

#include <cstdint>
#include <string>
#include <vector>

#include "lab/runs/matcher.h"
#include "mlndt/cloud/point_cloud.h"
#include "mlndt/common/progress.h"

namespace mlndt {

// The measurements at one size.
struct SizeResult {
  size_t points = 0;
  double map_ms = 0.0;  // Medians over the repetitions.
  double sampling_ms = 0.0;
  double solve_ms = 0.0;
  double total_ms = 0.0;
  size_t sampled_points = 0;
  size_t finest_cells = 0;  // Occupied cells on the finest layer (0 for NDT).
  int num_layers = 0;
  int iterations = 0;
  TerminationType termination = TerminationType::FAILURE;
  std::string message;
  double translation_error_m = 0.0;
  double rotation_error_deg = 0.0;
  bool ok = false;  // Not FAILURE, and within the error tolerances.
};

struct ScalingSettings {
  uint64_t seed = 1;    // The subsets' seeds derive from it and N.
  int repetitions = 3;  // Registrations per size; stage times are medians.
  double max_translation_error_m = 0.1;  // A larger error is a broken solve.
  double max_rotation_error_deg = 0.5;
};

// Draws the reference and the input (moved by reference_from_input^-1)
// subsets of `n` points of `merged`, registers the input from the identity
// `settings.repetitions` times and fills *result. False with *error when the
// reference's map cannot be built.
bool MeasureSize(const ScalingSettings& settings,
                 const MatcherOptions& options,
                 const PointCloud& merged,
                 size_t n,
                 const Isometry3d& reference_from_input,
                 SizeResult* result,
                 std::string* error);

// MeasureSize of every size in turn; `progress` (may be null, not owned)
// hears of each size.
bool MeasureSizes(const ScalingSettings& settings,
                  const MatcherOptions& options,
                  const PointCloud& merged,
                  const std::vector<size_t>& sizes,
                  const Isometry3d& reference_from_input,
                  ProgressCallback* progress,
                  std::vector<SizeResult>* results,
                  std::string* error);

}  // namespace mlndt
