#pragma once

// Errors in the paper's axes and units (Section 5.2, Tables 2-7). The paper
// works in 3DTK's left-handed frame with y up: its tx is lateral, ty
// vertical and tz forward, in centimetres; alpha, beta, gamma turn about
// them (beta is the heading), in degrees. Our clouds are right-handed with
// x forward, y left, z up (io.h reads 3DTK's .3d scans into that frame:
// x = z_3dtk, y = -x_3dtk, z = y_3dtk). An error is the paper's: estimated
// parameters minus the reference's, xi = (t, Eq. 7 angles).

#include <limits>
#include <vector>

#include "mlndt/common/types.h"

namespace mlndt {
namespace experiments {

// The six columns of the paper's tables.
enum PaperAxis { TX = 0, TY, TZ, ALPHA, BETA, GAMMA };

// "tx [cm]", ..., "γ [deg]".
const char* PaperAxisLabel(int axis);

// (tx, ty, tz [cm], alpha, beta, gamma [deg]) of estimate minus reference:
// tx = -dy, ty = dz, tz = dx, alpha = -d(beta_ours), beta = d(gamma_ours),
// gamma = d(alpha_ours) (the turn about each axis, with its sign taken
// from the right-handed frame).
Vector6d PaperAxesError(const Isometry3d& reference,
                        const Isometry3d& estimate);

// The statistics the paper tabulates for one column.
struct ColumnStats {
  size_t count = 0;
  double mean = std::numeric_limits<double>::quiet_NaN();      // Signed.
  double std = std::numeric_limits<double>::quiet_NaN();       // Sample.
  double max_abs = std::numeric_limits<double>::quiet_NaN();   // |.|.
  double mean_abs = std::numeric_limits<double>::quiet_NaN();  // Fig. 17.
};

ColumnStats ComputeColumnStats(const std::vector<double>& values);

}  // namespace experiments
}  // namespace mlndt
