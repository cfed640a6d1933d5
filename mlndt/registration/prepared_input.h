#pragma once

// An input scan filtered and sampled once, for registering it from several
// starts (a localiser exploring its prior, an odometry's recovery search):
//
//   PreparedInput prepared;
//   PrepareInput(options, input, &prepared);
//   for (const Isometry3d& start : starts) {
//     Register(options, reference_map, prepared, start, &summary);
//   }
//
// Register's first step (registration.h) drops the returns the range filter
// rejects and samples the rest (ML-NDT Section 4.3); neither depends on the
// initial guess, and the sampling is seeded (point_sampler.h), so every
// start samples the same points. PrepareInput does that step once; Register
// on the prepared input is the rest, and gives the summary Register on the
// cloud gives (pose, trace, scores, verdict and messages; a FAILURE the input
// causes as well), except the times: sampling_time_s is the preparation's,
// and total_time_s leaves it out.

#include <string>
#include <vector>

#include "mlndt/cloud/point_cloud.h"
#include "mlndt/common/types.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/registration/registration_options.h"
#include "mlndt/registration/registration_summary.h"

namespace mlndt {

// What PrepareInput leaves; read, not written, by its users.
struct PreparedInput {
  // Why the input cannot be registered: a problem of the cloud itself
  // (empty, non-finite) or of the options it was prepared with; checked
  // before the initial guess. "" when none.
  std::string input_error;
  // Why nothing is left after the range filter or the sampling; "" when the
  // samples exist. Reported after the initial guess's check, as Register
  // on the cloud orders them.
  std::string sampling_error;
  // RegistrationSummary's counts and time of the filter and the sampling.
  size_t input_points = 0;
  size_t range_filtered_points = 0;
  size_t sampled_points = 0;
  double sampling_time_s = 0.0;
  // The sampled points about their centroid `centre` (the frame the solver
  // works in), and their RMS distance from it [m].
  std::vector<Eigen::Vector3d> points;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double rms_range_m = 0.0;

  bool ok() const { return input_error.empty() && sampling_error.empty(); }
};

// Checks `input`, drops what options.range_filter rejects and samples the
// rest with options.sampling, into *prepared. Returns prepared->ok().
bool PrepareInput(const RegistrationOptions& options,
                  const PointCloud& input,
                  PreparedInput* prepared);

// Register (registration.h) of a prepared input. The range filter and the
// sampling it was prepared with apply; options.range_filter and
// options.sampling do not (nor, as for any built map, options.grid).
// `input` must outlive the call only.
void Register(const RegistrationOptions& options,
              const LayeredGrid& reference_map,
              const PreparedInput& input,
              const Isometry3d& initial_reference_from_input,
              RegistrationSummary* summary);

}  // namespace mlndt
