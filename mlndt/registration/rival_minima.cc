#include "mlndt/registration/rival_minima.h"

#include "mlndt/common/internal/check_option.h"
#include "mlndt/common/pose.h"

namespace mlndt {
namespace {

// center * delta for a motion in the center's (the sensor's) frame.
Isometry3d Moved(const Isometry3d& center,
                 double x_m,
                 double y_m,
                 double yaw_deg) {
  return center * PoseVectorToIsometry(
                      PoseVectorFromDegrees(x_m, y_m, 0.0, 0.0, 0.0, yaw_deg));
}

}  // namespace

bool MinimaSeparation::IsValid(std::string* error) const {
  MLNDT_OPTION_GT(cell_size_m, 0.0);
  MLNDT_OPTION_GE(max_cells, 0.0);
  MLNDT_OPTION_GE(max_rotation_deg, 0.0);
  MLNDT_OPTION_GE(lever_m, 0.0);
  return true;
}

bool RivalMinimaOptions::IsValid(std::string* error) const {
  if (!separation.IsValid(error)) return false;
  MLNDT_OPTION_GE(as_well_margin, 0.0);
  return true;
}

bool DistinctMinima(const MinimaSeparation& separation,
                    const Isometry3d& a,
                    const Isometry3d& b) {
  const double t = TranslationErrorM(a, b);
  const double r = RotationErrorRad(a, b);
  if (separation.lever_m > 0.0) {
    return (t + r * separation.lever_m) / separation.cell_size_m >
           separation.max_cells;
  }
  return t > separation.max_cells * separation.cell_size_m ||
         r * kRadToDeg > separation.max_rotation_deg;
}

RivalMinimaSummary FindRivalMinimum(const RivalMinimaOptions& options,
                                    const std::vector<Isometry3d>& minima,
                                    size_t result,
                                    const MinimumFit& fit) {
  RivalMinimaSummary summary;
  const Isometry3d& at = minima[result];
  bool scored = false;
  double result_fit = 0.0;
  for (size_t i = 0; i < minima.size(); ++i) {
    if (i == result || !DistinctMinima(options.separation, at, minima[i])) {
      continue;
    }
    if (!scored) {
      result_fit = fit(result);
      scored = true;
    }
    // Not clearly worse: the data do not decide between the two.
    if (fit(i) < result_fit - options.as_well_margin) continue;
    summary.rival = static_cast<int>(i);
    summary.apart_m = TranslationErrorM(at, minima[i]);
    summary.apart_deg = RotationErrorRad(at, minima[i]) * kRadToDeg;
    return summary;
  }
  return summary;
}

std::vector<Isometry3d> StartsAround(const Isometry3d& center,
                                     double step_m,
                                     double turn_deg) {
  std::vector<Isometry3d> starts;
  if (step_m > 0.0) {
    for (double sign : {1.0, -1.0}) {
      starts.push_back(Moved(center, sign * step_m, 0.0, 0.0));
      starts.push_back(Moved(center, 0.0, sign * step_m, 0.0));
    }
  }
  if (turn_deg > 0.0) {
    for (double sign : {1.0, -1.0}) {
      starts.push_back(Moved(center, 0.0, 0.0, sign * turn_deg));
    }
  }
  return starts;
}

}  // namespace mlndt
