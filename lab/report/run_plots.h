#pragma once

// Top views of a run over scans, drawn with gnuplot: trajectory_xy.png of
// mlndt_odometry and of mlndt_localize (the data and script in
// dir/plot_data). A sequence run's figures: sequence_plots.h.

#include <string>
#include <vector>

#include "mlndt/common/types.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/odometry/odometry.h"
#include "mlndt/pipeline/localizer.h"

namespace mlndt {

// trajectory_xy.png: the estimate (fallbacks marked) and the reference.
bool WriteOdometryPlot(const std::string& gnuplot,
                       const std::string& dir,
                       const std::vector<OdometryResult>& results,
                       const std::vector<Isometry3d>& reference,
                       std::string* error);

// trajectory_xy.png: the finest layer's cell means (every k-th, at most
// plot_max_cells) and the trajectory, seen from above.
bool WriteLocalizationPlot(const std::string& dir,
                           const LayeredGrid& map,
                           const std::vector<LocalizationResult>& results,
                           int plot_max_cells,
                           const std::string& gnuplot,
                           std::string* error);

}  // namespace mlndt
