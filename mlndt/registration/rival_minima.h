#pragma once

// Rival minima: explore the objective (ML-NDT Eq. 10) from other starts and
// compare the minima found with the result. A result is trusted only when
// no distinct minimum fits as well: otherwise the data do not decide
// between the two poses, and the verdict is DEGENERATE (or, where the
// question is whether the result is a minimum at all, not confirmed).
//
// One mechanism, three users:
//  - registration's verdict (registration/internal/attempts.cc): the
//    minima every run of one registration converged to, compared on the
//    last layer's inliers;
//  - odometry's confirmation (odometry/confirm_pose.h): one run from
//    beyond the pose along its correction; any distinct minimum it ends in
//    means the pose is not one the registration returns to;
//  - map localisation (pipeline/localization_prior.h): runs from the
//    prior's half-bound, compared by inlier fraction.
//
// What differs between them is a parameter, not a code path:
//  - MinimaSeparation::lever_m: the registration compares minima in the
//    map's cell edges, where a turn moves the points by the angle times
//    their RMS range (lever_m > 0 adds the two); the odometry and the
//    localiser state their prediction and prior as separate translation
//    and rotation bounds (lever_m = 0: apart when either bound is passed);
//  - RivalMinimaOptions::as_well_margin, in the unit of the fit the caller
//    gives: the registration's fit is the inlier gain's z-score against the
//    result (a difference of inliers over the square root of those that
//    changed, so density-independent), the localiser's the inlier fraction;
//    the odometry asks only whether the run returned, so any distinct
//    minimum rivals the pose: it calls DistinctMinima alone;
//  - the starts: along the flattest direction for the registration
//    (the constraint probe found it flat, so a rival lies along it), beyond
//    the pose along the correction for the odometry (a slide along a weak
//    direction stops where its pull ran out, not at a minimum), on the
//    prior's half-bound for the localiser (another place within the prior
//    may look alike).

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "mlndt/common/types.h"

namespace mlndt {

// When two minima are distinct: farther apart than the basin of one.
struct MinimaSeparation {
  // The unit of max_cells [m]: the finest cell edge (or 1 for metres). > 0.
  double cell_size_m = 1.0;
  // Distinct when the translation (plus, with lever_m > 0, the rotation
  // [rad] times lever_m) exceeds max_cells * cell_size_m: within a fraction
  // of a cell most points keep their cells, one basin. >= 0.
  double max_cells = 0.5;
  // With lever_m = 0: also distinct when turned by more than this [deg].
  double max_rotation_deg = 180.0;
  // > 0: the rotation counts as the distance it moves a point at this
  // range [m] (the points' RMS range), added to the translation. >= 0.
  double lever_m = 0.0;

  bool IsValid(std::string* error) const;
};

// True when `a` and `b` are distinct minima by `separation`.
bool DistinctMinima(const MinimaSeparation& separation,
                    const Isometry3d& a,
                    const Isometry3d& b);

struct RivalMinimaOptions {
  MinimaSeparation separation;
  // A distinct minimum fits as well as the result unless its fit is below
  // the result's by more than this (in the caller's unit of fit; see
  // above). >= 0; +infinity: every distinct minimum rivals the result.
  double as_well_margin = 0.0;

  bool IsValid(std::string* error) const;
};

// What the comparison found.
struct RivalMinimaSummary {
  int rival = -1;        // Index of the first rival among the minima; -1: none.
  double apart_m = 0.0;  // Its translation from the result.
  double apart_deg = 0.0;  // Its rotation from the result.
  bool found() const { return rival >= 0; }
};

// The fit of minimum i (larger is better) in as_well_margin's unit; asked
// only of the result and of minima distinct from it, in order, until a
// rival is found (a fit may be costly to score).
using MinimumFit = std::function<double(size_t i)>;

// The first of `minima` distinct from minima[result] whose fit is not below
// the result's by more than options.as_well_margin.
RivalMinimaSummary FindRivalMinimum(const RivalMinimaOptions& options,
                                    const std::vector<Isometry3d>& minima,
                                    size_t result,
                                    const MinimumFit& fit);

// The starts each user explores from are laid out where the user is
// (above): registration/internal/attempts.cc (MovedAlong, yaw seeds),
// odometry/confirm_pose.h (ConfirmationStart); the localiser's here.

// `center` moved in its own frame by +-step_m along x and y (when step_m >
// 0), then turned by +-turn_deg about z (when turn_deg > 0), in the order
// +x, +y, -x, -y, +turn, -turn: which way a sensor is off is not known.
std::vector<Isometry3d> StartsAround(const Isometry3d& center,
                                     double step_m,
                                     double turn_deg);

}  // namespace mlndt
