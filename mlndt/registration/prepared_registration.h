#pragma once

// Registrations of one prepared input (prepared_input.h) from several
// starts with one set of options, sharing the solver's set-up:
//
//   PreparedRegistration registration(options, prepared);
//   for (const Isometry3d& start : starts) {
//     registration.Register(reference_map, start, &summary);
//   }
//
// Register on the prepared input makes a backend per call; the Ceres
// backend builds a cost function per sample and a ceres::Problem per point
// stride (ceres_backend.h). Here the backend is made and given the samples
// once, and every run solves the same Problems again from its own start, as
// the stages of one registration already do (the same blocks in the same
// order): each summary is the one Register on the prepared input gives,
// times aside (solve_time_s and total_time_s leave out what was built
// before).
//
// Holds state (the backend): one object per thread. `input` must outlive
// it; `options` is copied.

#include <memory>
#include <string>

#include "mlndt/common/types.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/registration/prepared_input.h"
#include "mlndt/registration/registration_options.h"
#include "mlndt/registration/registration_summary.h"

namespace mlndt {

class Backend;

class PreparedRegistration {
 public:
  PreparedRegistration(const RegistrationOptions& options,
                       const PreparedInput& input);
  ~PreparedRegistration();
  PreparedRegistration(const PreparedRegistration&) = delete;
  PreparedRegistration& operator=(const PreparedRegistration&) = delete;

  // Register(options, reference_map, input, initial, summary), with the
  // options and the input given to the constructor.
  void Register(const LayeredGrid& reference_map,
                const Isometry3d& initial_reference_from_input,
                RegistrationSummary* summary);

 private:
  const RegistrationOptions options_;
  const PreparedInput& input_;
  std::string options_error_;         // options_.IsValid's message, or "".
  std::string backend_error_;         // CreateBackend's message, or "".
  std::unique_ptr<Backend> backend_;  // Given the samples once; or null.
};

}  // namespace mlndt
