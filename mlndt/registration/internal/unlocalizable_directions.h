#pragma once

// The translations the localizability (localizability.h) leaves free, added
// to a constraint analysis' degenerate directions: one function for the
// verdict (quality_check.cc, every judged pose) and the prior hold
// (attempts.cc, step 8: a result judged without the localizability test
// during the searches). Not installed.

#include <vector>

#include "mlndt/common/types.h"
#include "mlndt/cost/point_matches.h"
#include "mlndt/registration/quality_check.h"

namespace mlndt {
namespace internal {

// True when d is within about 25 deg of one of `directions` (either sign;
// all unit).
bool AlreadyNamed(const std::vector<Vector6d>& directions, const Vector6d& d);

// The translation's localizability of `matches` (the input points matched
// at the solution; inliers by options.inlier_gate) into *analysis
// (localizability, least_localizable_direction); the directions below
// options.min_localizability, unless AlreadyNamed, join its
// degenerate_directions and count in unlocalizable_directions. Returns the
// directions added (none when no inlier lies on a planar cell).
std::vector<Vector6d> AddUnlocalizableDirections(
    const std::vector<PointMatch>& matches,
    const QualityCheckOptions& options,
    ConstraintAnalysis* analysis);

}  // namespace internal
}  // namespace mlndt
