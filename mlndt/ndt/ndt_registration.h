#pragma once

// The conventional NDT baseline the paper compares ML-NDT against (Section
// 3, Eq. 4; Biber & Strasser, Magnusson's P2D-NDT): one grid of cubic cells
// over the reference scan (a one-layer LayeredGrid), Magnusson's Gaussian
// score (gaussian_score.h) over the sampled input points, minimised by
// Newton (MinimizeNewton) with a bounded step. Same summary as ML-NDT's
// Register (registration_summary.h), with one layer.
//
//   NdtOptions options;
//   RegistrationSummary summary;
//   RegisterNdt(options, reference, input, initial_reference_from_input,
//               &summary);

#include <string>

#include "mlndt/cloud/point_cloud.h"
#include "mlndt/cloud/range_filter.h"
#include "mlndt/common/types.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/ndt/gaussian_score.h"
#include "mlndt/registration/quality_check.h"
#include "mlndt/registration/registration_summary.h"
#include "mlndt/sampling/point_sampler.h"
#include "mlndt/solvers/newton_backend.h"

namespace mlndt {

class OptionTable;

struct NdtOptions {
  // Returns that are not measurements (range_filter.h), dropped from the
  // input and, when RegisterNdt builds the grid, the reference.
  RangeFilterOptions range_filter;
  // Cell edge [m]. 0: the paper's comparison cell, one layer-2 cell of the
  // ML-NDT map (q = 8) over the reference box, (V / 64)^(1/3) (Section 5.1;
  // ~15 m on a KITTI scan). PCL users run 1-2 m outdoors. 0, or in
  // [1e-3, 1e5].
  double cell_size_m = 0.0;
  // Cells with fewer points keep no distribution. In [4, 1e6].
  int min_points_per_cell = 5;
  // Covariance regularisation (ndt_cell.h): LayeredGridOptions' floors,
  // every cell scored with its whole covariance (Magnusson's NDT).
  CellRegularization regularization = WholeCovarianceRegularization();
  // Magnusson's outlier ratio r, in (0, 1) (gaussian_score.h).
  double outlier_ratio = 0.55;
  // Cells a point is scored in: its own (DIRECT1, as the paper) or also the
  // 6 face neighbours (DIRECT7).
  NdtNeighbors neighbors = NdtNeighbors::DIRECT1;
  // Which input points are scored (Section 4.3).
  SamplingOptions sampling;
  // Newton iterations. In [1, 10000].
  int max_iterations = 50;
  // Converged when a successful step has ||delta xi|| below this (metres
  // and radians). In [1e-12, 1].
  double step_tolerance = 1e-4;
  // Longest Newton step ||delta xi|| (metres and radians mixed); 0 =
  // unbounded. Away from the minimum the Gaussian score's Hessian is
  // indefinite, and its Newton step runs far along the negative curvature
  // (PCL bounds its step for the same reason). In [0, 1e3].
  double max_step_norm = 0.5;
  NewtonOptions newton;
  // OpenMP threads for the map build and the score. In [1, 256].
  int num_threads = 1;
  // FAILURE when fewer than this fraction of the sampled points are matched
  // at the solution. In [0, 1].
  double min_matched_fraction = 0.05;
  // The verdict, as ML-NDT's (quality_check.h: the same function judges
  // both). It is judged on cells of ML-NDT's finest size
  // (LayeredGridOptions' default, built from the reference for it), not on
  // the NDT grid: the check's thresholds are measured on those cells.
  QualityCheckOptions quality_check;

  bool IsValid(std::string* error) const;
};

// NdtOptions's fields: name, unit, valid range and help (option_table.h).
const OptionTable& NdtOptionsTable();

// The one-layer map options of the NDT grid of `reference` (the cell edge of
// options, or the paper's cell over its bounding box). False with *error for
// an empty cloud or one without volume.
bool NdtGridOptions(const NdtOptions& options,
                    const PointCloud& reference,
                    LayeredGridOptions* grid_options,
                    std::string* error);

// Builds the grid of `reference`, then registers.
void RegisterNdt(const NdtOptions& options,
                 const PointCloud& reference,
                 const PointCloud& input,
                 const Isometry3d& initial_reference_from_input,
                 RegistrationSummary* summary);

// Registers against the finest layer of a map built beforehand (for NDT,
// with NdtGridOptions: one layer; cell_size_m, min_points_per_cell and
// regularization of options do not apply). The verdict is judged on that
// layer when its cells are at most twice ML-NDT's finest cell; on coarser
// cells the fit cannot be checked, and a converged result is reported as
// NO_CONVERGENCE saying so (the cloud overload checks it).
void RegisterNdt(const NdtOptions& options,
                 const LayeredGrid& reference_map,
                 const PointCloud& input,
                 const Isometry3d& initial_reference_from_input,
                 RegistrationSummary* summary);

}  // namespace mlndt
