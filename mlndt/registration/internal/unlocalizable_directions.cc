#include "mlndt/registration/internal/unlocalizable_directions.h"

#include <cmath>

#include "mlndt/registration/localizability.h"

namespace mlndt {
namespace internal {

bool AlreadyNamed(const std::vector<Vector6d>& directions, const Vector6d& d) {
  for (const Vector6d& named : directions) {
    if (std::abs(named.dot(d)) > 0.9) return true;
  }
  return false;
}

std::vector<Vector6d> AddUnlocalizableDirections(
    const std::vector<PointMatch>& matches,
    const QualityCheckOptions& options,
    ConstraintAnalysis* analysis) {
  std::vector<Vector6d> added;
  const Localizability localizability =
      LocalizabilityOf(matches, options.inlier_gate);
  if (localizability.planar_points == 0) return added;
  Eigen::Index least = 0;
  analysis->localizability = localizability.share.minCoeff(&least);
  analysis->least_localizable_direction = Vector6d::Zero();
  analysis->least_localizable_direction.head<3>() =
      localizability.directions.col(least);
  for (int k = 0; k < 3; ++k) {
    Vector6d d = Vector6d::Zero();
    d.head<3>() = localizability.directions.col(k);
    if (localizability.share(k) >= options.min_localizability ||
        AlreadyNamed(analysis->degenerate_directions, d)) {
      continue;
    }
    analysis->degenerate_directions.push_back(d);
    analysis->unlocalizable_directions++;
    added.push_back(d);
  }
  return added;
}

}  // namespace internal
}  // namespace mlndt
