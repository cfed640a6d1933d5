#pragma once

// Everything a registration is configured by, one component each: the map,
// the input sampling, the layer schedule, the objective and the backend.
// Each component's defaults are the library's (docs/defaults.md says why and
// how each was measured); PaperRegistrationOptions() is the paper's
// configuration, for reproducing Section 5.

#include <string>
#include <vector>

#include "mlndt/cloud/range_filter.h"
#include "mlndt/cost/objective_options.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/registration/quality_check.h"
#include "mlndt/sampling/point_sampler.h"
#include "mlndt/schedule/layer_scheduler.h"
#include "mlndt/solvers/backend_factory.h"

namespace mlndt {

class OptionTable;

// How far the initial guess may be from the truth, when the caller knows
// (odometry, a constant-velocity prediction, a prior map pose). It picks the
// start layer (Section 5.3's guideline: the better the guess, the finer the
// start) and bounds how far the result may move from the guess before it is
// checked against a finest-layer-only run from the guess.
struct InitialGuessUncertainty {
  // False: nothing is known about the guess (schedule.start_layer applies).
  bool given = false;
  double translation_m = 0.0;  // In [0, 1e4].
  double rotation_deg = 0.0;   // In [0, 180].

  bool IsValid(std::string* error) const;
};

// InitialGuessUncertainty's fields: name, unit, valid range and help
// (option_table.h).
const OptionTable& InitialGuessUncertaintyTable();

// Runs again when the result fails the quality check (a wrong local
// minimum, most often a rotation beyond the coarse layers' basin): from the
// guess turned by each yaw seed about the input's centroid, in order, until
// one passes; free when the first run passes. With a known guess
// uncertainty only the seeds within its rotation are tried. And when a
// converged result lies on a weakly constrained direction: the search
// along it (below), which finds the better of several minima.
struct RetryOptions {
  // Yaw turns [deg], each in [-180, 180]; at most 36. Empty: no retry.
  std::vector<double> yaw_seeds_deg = {45, -45, 90, -90, 135, -135, 180};
  // Rounds of the search along the flattest weak direction (the probe's,
  // quality_check.h): the last layer runs again from the solution moved one
  // cell edge along it, both ways; a solution in another basin that fits
  // better replaces it, and the search goes on from there. A weakly
  // constrained direction (a road seen within a few metres) holds several
  // minima, and the one nearest the guess need not be the best. In [0, 16];
  // 0 = off.
  int weak_direction_rounds = 4;
  // The search runs only when the probe kept at least this share of the
  // inliers one cell edge along the flattest direction (flatness,
  // quality_check.h): a direction where a cell away fits nearly as well
  // may hold another minimum. The scan-pattern check asks the same share of
  // the planar cells along the weakest translation. In [0, 1].
  double weak_direction_min_flatness = 0.6;
  // The scan-pattern check (attempts.h, step 4) runs on a converged result
  // whose translation is within this many last-layer cell edges of zero:
  // where the two scans' sensors coincide, a spinning LiDAR's rings fall
  // into the cells of the reference's own rings and fit them whatever the
  // motion. Beyond half a cell they fall into other cells. The check also
  // looks for the scene's own minimum from (1 + this) cell edges along the
  // weakest translation, where the planar cells keep at least
  // weak_direction_min_flatness of their inliers one cell edge along it.
  // In [0, 4]; 0 = off.
  double scan_pattern_reach_cells = 0.5;

  bool IsValid(std::string* error) const;
};

// RetryOptions's fields: name, unit, valid range and help (option_table.h).
const OptionTable& RetryOptionsTable();

struct RegistrationOptions {
  // Returns of the raw scans that are not measurements (at the sensor, at a
  // saturated maximum range): dropped from the input, and from the reference
  // when Register builds its map.
  RangeFilterOptions range_filter;
  // The reference map (used by the Register overload that builds it).
  LayeredGridOptions grid;
  // Which input points become residuals (Section 4.3).
  SamplingOptions sampling;
  // Start layer, iterations per layer, convergence of the last layer.
  LayerScheduleOptions schedule;
  // What is minimised: unmatched-point policy and robust loss (Eq. 10).
  ObjectiveOptions objective;
  // Which minimiser, with its options.
  BackendOptions backend;
  // Threads for the whole registration: the map build (when Register builds
  // the map) and the backend (the Ceres backend's residual evaluation, or
  // OpenMP threads over points for newton and lm). In [1, 256]. Work too
  // small to share stays on one thread (common/thread_budget.h). With the
  // Ceres backend the result has the same bits for any count; newton and lm
  // sum per-thread partials (same bits for the same count). OpenMP threads
  // busy-wait between parallel regions: on a loaded machine, run newton and
  // lm with OMP_WAIT_POLICY=passive.
  int num_threads = 1;
  // The result is reported as FAILURE when fewer than this fraction of the
  // sampled points are matched to a cell at the solution. In [0, 1].
  double min_matched_fraction = 0.05;
  // Whether the result can be trusted (quality_check.h).
  QualityCheckOptions quality_check;
  // How good the initial guess is (see above).
  InitialGuessUncertainty initial_uncertainty;
  // Runs from turned guesses when the first fails the quality check.
  RetryOptions retry;

  bool IsValid(std::string* error) const;
};

// RegistrationOptions's fields: name, unit, valid range and help
// (option_table.h).
const OptionTable& RegistrationOptionsTable();

// The paper's configuration (Sections 4 and 5): n = 4 layers, start on
// layer 2, 3 iterations a layer with every sampled point, the plain Eq. (10)
// sum over own cells, Newton. GBS sampling and the covariance
// regularisation (including its absolute floor) and the range filter are the
// library's.
RegistrationOptions PaperRegistrationOptions();

}  // namespace mlndt
