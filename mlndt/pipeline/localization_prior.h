#pragma once

// The verdict of a scan localised from a guess whose uncertainty is stated
// (the prior): a localisation of that prior is a pose within it that no
// other pose within it fits as well. Registration alone (registration.h)
// answers "did the minimiser reach a minimum that fits"; a map holds many
// places that look alike (a courtyard's four façades, a colonnade's
// arches), and a wide prior reaches several of them.
//
// RegisterWithinPrior registers the scan from the guess, with the prior as
// the registration's initial uncertainty (it picks the start layer), and
// then:
//  1. explores the prior: when the prior is wider than the map's finest
//     cell (translation) or than PriorCheckOptions::explore_min_rotation_deg,
//     the scan is registered again from starts on the prior's half-bound
//     around the guess: moved by +-translation/2 along the sensor's x and y,
//     and turned by +-rotation/2 about the sensor's z (the guess's own
//     frame: which way a hand-held sensor is off is not known;
//     StartsAround). Each start gets the same prior;
//  2. keeps the usable results (IsSolutionUsable) that lie within the prior
//     (4) and fit the map as well as the map's own points do (below); of
//     those the one with the most inliers (FitQuality::
//     inlier_fraction on the finest layer; every run samples the same points
//     and scores them on the same layer), the lower mean score on a tie;
//  3. calls the scan ambiguous (DEGENERATE, "another minimum within the
//     prior fits as well") when another kept result lies farther than half
//     a finest cell edge or explore_distinct_rotation_deg from it and has an
//     inlier fraction within ambiguity_inlier_margin of it: the data do not
//     decide between two places the prior allows (a rival minimum,
//     registration/rival_minima.h, as the registration's own verdict and
//     the odometry's confirmation ask it);
//  4. calls a usable result outside the prior LOW_QUALITY ("outside the
//     prior"): |t| > translation_m or angle > rotation_deg of
//     guess^-1 * result. A result 6.9 m from a guess stated good to 2 m is
//     not a localisation of that guess, however well it fits.
// The map's own points: a cell's points follow its Gaussian, and a share
// P(chi2_3 <= g^2) of them lies within the Mahalanobis gate g of the
// quality check (FitQuality's inlier_fraction; 0.971 at g = 3). A scan of
// the place the map holds, at its true pose, is explained by the map as
// its own points are where the map holds cells: a result whose inlier
// fraction among the points whose own cell is occupied (inlier_fraction /
// own_cell_fraction: the points beyond the mapped region are left out) is
// below min_fit_ratio times that share fits the map worse than the map fits
// itself, and is not kept (a wrong pose in a look-alike place fits part of
// the scan). A map of another session (moved objects) needs a lower ratio.
//
// The map's own points are a map accumulated from many viewpoints (as
// mlndt_map builds one from a sequence): a map of one sparse scan fits its
// neighbours' right poses worse, and needs a lower ratio or 0 (docs/maps.md).
//
// A prior that is not given (InitialGuessUncertainty::given false): none of
// 1-4 runs; the registration's verdict stands.

#include <string>

#include "mlndt/cloud/point_cloud.h"
#include "mlndt/common/types.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/registration/registration.h"

namespace mlndt {

struct PriorCheckOptions {
  // Explore the prior from other starts (step 1 above).
  bool explore = true;
  // A prior narrower than the finest cell edge in translation and than this
  // in rotation is not explored: one basin holds it. [deg], in [0, 180].
  double explore_min_rotation_deg = 10.0;
  // Two results are distinct minima when farther apart than half a finest
  // cell edge or than this rotation [deg]. In (0, 180].
  double explore_distinct_rotation_deg = 5.0;
  // Another minimum whose inlier fraction is at least the best's minus this
  // fits as well (step 3). Chosen on a train half of starts
  // (docs/maps.md). In [0, 1].
  double ambiguity_inlier_margin = 0.02;
  // The fit the map's own points give, times this, is the least a kept
  // result needs (above). Chosen on a train half of starts
  // (docs/maps.md). In [0, 1]; 0 = off.
  double min_fit_ratio = 0.95;

  bool IsValid(std::string* error) const;
};

// What the prior's checks found.
struct PriorCheckSummary {
  int explored_starts = 0;  // Registrations besides the one from the guess.
  double explored_time_s = 0.0;  // Their total_time_s, summed.
  int usable_within = 0;         // Usable results within the prior (all runs).
  bool moved_to_other_start = false;  // The kept result is an explored one.
  // The kept result's distance from the guess [m], [deg].
  double from_guess_m = 0.0;
  double from_guess_deg = 0.0;
};

// P(chi2_3 <= gate^2): the share of a 3D Gaussian's samples within
// Mahalanobis distance `gate` of its mean.
double GaussianInlierShare(double gate);

// guess^-1 * pose within `prior` (both bounds; true when not given).
bool WithinPrior(const InitialGuessUncertainty& prior,
                 const Isometry3d& guess,
                 const Isometry3d& pose);

// Registers `scan` onto `map` from `guess` with uncertainty `prior` and
// applies steps 1-4 to the verdict; *summary is the kept registration's,
// its termination and message changed by steps 3-4, its total_time_s that
// of every run. `check` may be null.
void RegisterWithinPrior(const PriorCheckOptions& options,
                         const RegistrationOptions& registration,
                         const LayeredGrid& map,
                         const PointCloud& scan,
                         const Isometry3d& guess,
                         const InitialGuessUncertainty& prior,
                         RegistrationSummary* summary,
                         PriorCheckSummary* check);

}  // namespace mlndt
