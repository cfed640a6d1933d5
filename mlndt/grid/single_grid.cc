#include "mlndt/grid/single_grid.h"

#include <glog/logging.h>

#include <cmath>
#include <vector>

#include "mlndt/common/check_option.h"
#include "mlndt/grid/cell_index.h"

namespace mlndt {
namespace {

// Zeroth, first and second moments of a cell's points, relative to the box
// centre so that coordinates far from the origin keep their precision.
struct Moments {
  int64_t count = 0;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d outer = Eigen::Matrix3d::Zero();
};

}  // namespace

bool SingleGridOptions::IsValid(std::string* error) const {
  MLNDT_OPTION_GE(cell_size_m, 0.0);
  MLNDT_OPTION_GE(min_points_per_cell, 4);
  MLNDT_OPTION_GT(regularization.min_eigenvalue_ratio, 0.0);
  MLNDT_OPTION_LE(regularization.min_eigenvalue_ratio, 1.0);
  MLNDT_OPTION_GE(regularization.min_eigenvalue_m2, 0.0);
  return true;
}

double PaperNdtCellSize(const Eigen::Vector3d& extent) {
  LayeredGridOptions options;
  options.division_constant = 8;
  options.num_layers = 2;
  options.finest_cell_size_m = 0.0;
  const std::vector<double> sizes = LayerCellSizes(options, extent);
  return sizes.size() == 2 ? sizes[1] : 0.0;
}

bool BuildSingleGrid(const SingleGridOptions& options,
                     const PointCloud& reference,
                     NdtLayer* grid,
                     LayerInfo* info,
                     std::string* error) {
  CHECK(grid != nullptr);
  CHECK(info != nullptr);
  CHECK(error != nullptr);
  if (!options.IsValid(error)) return false;
  if (reference.empty()) {
    *error = "the reference cloud is empty";
    return false;
  }
  if (!AllFinite(reference)) {
    *error = "the reference cloud has non-finite points";
    return false;
  }
  const Eigen::AlignedBox3d bounds = BoundingBox(reference);
  const Eigen::Vector3d extent = bounds.sizes();
  if (!(extent.maxCoeff() > 0.0)) {
    *error = "all reference points coincide: the bounding box has no volume";
    return false;
  }
  const double cell_size = options.cell_size_m > 0.0 ? options.cell_size_m
                                                     : PaperNdtCellSize(extent);
  // floor(extent / k) + 1 cells per axis, as the layers of the ML-NDT map.
  const Eigen::Vector3d cells = (extent / cell_size).array().floor() + 1.0;
  if (!(cell_size > 0.0) || cells.maxCoeff() > 1e6 || cells.prod() > 4e18) {
    *error = "cell size " + std::to_string(cell_size) +
             " m gives too many cells over a " +
             std::to_string(extent.maxCoeff()) + " m box";
    return false;
  }
  const Eigen::Vector3i dims = cells.cast<int>();
  const Eigen::Vector3d origin = bounds.min();
  const Eigen::Vector3d centre = bounds.center();

  // Splitting process: every point goes to its cell.
  const int64_t num_grid_cells = int64_t{dims.x()} * dims.y() * dims.z();
  CellIndex index(num_grid_cells);
  std::vector<int64_t> raw_keys;
  std::vector<Moments> moments;
  const double inverse_size = 1.0 / cell_size;
  for (const Eigen::Vector3d& p : reference.points()) {
    // Points lie inside the box; min() keeps rounding at the max face inside.
    const Eigen::Vector3i ijk = ((p - origin) * inverse_size)
                                    .array()
                                    .floor()
                                    .cast<int>()
                                    .max(0)
                                    .min(dims.array() - 1);
    const int64_t key =
        ijk.x() + int64_t{dims.x()} * (ijk.y() + int64_t{dims.y()} * ijk.z());
    const int32_t slot =
        index.FindOrInsert(key, static_cast<int32_t>(raw_keys.size()));
    if (slot == static_cast<int32_t>(raw_keys.size())) {
      raw_keys.push_back(key);
      moments.emplace_back();
    }
    Moments& m = moments[static_cast<size_t>(slot)];
    const Eigen::Vector3d d = p - centre;
    ++m.count;
    m.sum += d;
    m.outer += d * d.transpose();
  }

  // Generative process: mean (Eq. 2), unbiased covariance (Eq. 3), regularised.
  LayerInfo layer_info;
  layer_info.layer = 1;
  layer_info.cell_size_m = cell_size;
  layer_info.dims = dims;
  std::vector<NdtCell> kept;
  std::vector<int64_t> keys;
  for (size_t i = 0; i < raw_keys.size(); ++i) {
    const Moments& m = moments[i];
    if (m.count < options.min_points_per_cell) {
      ++layer_info.sparse_cells;
      continue;
    }
    const double n = static_cast<double>(m.count);
    const Eigen::Vector3d mean = m.sum / n;
    const Eigen::Matrix3d covariance =
        (m.outer - n * mean * mean.transpose()) / (n - 1.0);
    NdtCell cell;
    if (!MakeNdtCell(static_cast<int32_t>(m.count),
                     mean + centre,
                     covariance,
                     options.regularization,
                     &cell)) {
      ++layer_info.degenerate_cells;
      continue;
    }
    kept.push_back(cell);
    keys.push_back(raw_keys[i]);
  }
  layer_info.occupied_cells = kept.size();
  *grid = NdtLayer(origin, cell_size, dims, std::move(kept), std::move(keys));
  *info = layer_info;
  return true;
}

}  // namespace mlndt
