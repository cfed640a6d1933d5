#pragma once

// The prior along the directions the data leave free. A registration given
// a prior (RegistrationOptions::initial_uncertainty: the initial guess with
// a stated uncertainty) returns a pose that does not move from the guess
// along the directions its data do not constrain: the constraint analysis'
// degenerate directions (quality_check.h: the ratio, the localizability,
// the probe, a rival minimum). Along those the objective is flat, so where
// the solver stopped there says nothing about the pose; the prior does.
//
// As X-ICP's localizability-aware optimisation (Tuna et al. 2023, which
// constrains the update in the degenerate directions to zero), with the
// pose in the scaled left perturbation delta = [dt; omega L] about the
// input's centroid (the rows of quality_check.h; L the points' RMS range):
//  1. F: an orthonormal basis of the free directions, V: of the rest;
//  2. the update from the guess g to the solution x, delta(g, x), loses its
//     free part: x' = g moved by (I - F F^T) delta(g, x);
//  3. the objective (ML-NDT Eq. 10 on the last layer) is minimised over V
//     alone from x' by Gauss-Newton steps y = -(V^T H V)^-1 V^T grad (H, grad
//     in delta: J^T H_xi J, J^T grad_xi, J = d xi / d delta), each kept only
//     when the score does not rise: the constrained part converges to the
//     data's optimum with the free part held at the prior's value;
//  4. the covariance in delta: the Laplace covariance 2 (V^T H V)^-1 on V
//     (Eq. 11) and the prior's on F, F^T P F with P = diag(s_t^2 I, (s_r L)^2
//     I), the stated bounds taken as one standard deviation (a bound is at
//     least that): C = V 2 (V^T H V)^-1 V^T + F F^T P F F^T, then J C J^T.
// Without a prior, or with no free direction, nothing changes.

#include "mlndt/common/types.h"
#include "mlndt/registration/internal/attempts.h"
#include "mlndt/registration/registration_options.h"

namespace mlndt {
namespace internal {

// Applies 1-4 to *attempt (in the anchor's frame, from `initial_local`)
// when options.initial_uncertainty is given, the attempt has a solution
// and its constraint analysis names a free direction: moves its pose,
// re-evaluates its score and fit there, sets its held covariance. The
// verdict stands (the data still leave those directions free). Returns the
// number of free directions held (0: nothing changed).
int HoldPriorAlongFreeDirections(const RegistrationOptions& options,
                                 const Problem& problem,
                                 const Vector6d& initial_local,
                                 Attempt* attempt);

}  // namespace internal
}  // namespace mlndt
