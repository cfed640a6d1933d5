#pragma once

// The ML-NDT registration facade, shaped like ceres::Solve:
//
//   RegistrationOptions options;          // or PaperRegistrationOptions()
//   RegistrationSummary summary;
//   Register(options, reference_map, input, initial_reference_from_input,
//            &summary);
//   if (summary.IsSolutionUsable()) use(summary.reference_from_input);
//
// It samples the input scan (Section 4.3), hands the samples and the
// objective to the backend once, runs the layer schedule (Table 1), and
// reports the pose, a per-iteration trace, counts, timings, the final score
// and the score's Hessian with the pose covariance derived from it. Invalid
// options or unusable input give a FAILURE summary with a message; nothing
// aborts. The conventional NDT baseline has its own entry point
// (ndt/ndt_registration.h) and the same summary.

#include "mlndt/cloud/point_cloud.h"
#include "mlndt/common/types.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/registration/registration_options.h"
#include "mlndt/registration/registration_summary.h"

namespace mlndt {

// Registers `input` against a map built beforehand (options.grid and
// options.num_threads' use for the map do not apply).
void Register(const RegistrationOptions& options,
              const LayeredGrid& reference_map,
              const PointCloud& input,
              const Isometry3d& initial_reference_from_input,
              RegistrationSummary* summary);

// Builds the map of `reference` with options.grid, then registers.
void Register(const RegistrationOptions& options,
              const PointCloud& reference,
              const PointCloud& input,
              const Isometry3d& initial_reference_from_input,
              RegistrationSummary* summary);

}  // namespace mlndt
