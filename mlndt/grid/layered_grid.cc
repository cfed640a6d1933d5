#include "mlndt/grid/layered_grid.h"

#include <cmath>
#include <sstream>

#include "mlndt/common/check_option.h"

namespace mlndt {
namespace {

// Zeroth, first and second moments of a cell's points, relative to a fixed
// centre (the box centre) so that far-away coordinates keep their precision.
struct Moments {
  int64_t count = 0;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d outer = Eigen::Matrix3d::Zero();

  void Add(const Eigen::Vector3d& d) {
    ++count;
    sum += d;
    outer.selfadjointView<Eigen::Upper>().rankUpdate(d);  // Upper triangle only.
  }
  void Merge(const Moments& other) {
    count += other.count;
    sum += other.sum;
    outer += other.outer;
  }
};

// Cells of one layer that received points, in order of first appearance.
struct RawLayer {
  std::vector<int64_t> keys;
  std::vector<Moments> moments;
};

struct LayerGeometry {
  double cell_size = 0.0;
  Eigen::Vector3i dims = Eigen::Vector3i::Zero();
  int64_t num_grid_cells() const { return int64_t{dims.x()} * dims.y() * dims.z(); }
  int64_t Key(const Eigen::Vector3i& ijk) const {
    return ijk.x() + int64_t{dims.x()} * (ijk.y() + int64_t{dims.y()} * ijk.z());
  }
};

// Splitting process for one layer: every point goes to its cell.
RawLayer BinPoints(const std::vector<Eigen::Vector3d>& points,
                   const Eigen::Vector3d& origin,
                   const Eigen::Vector3d& centre,
                   const LayerGeometry& geometry) {
  RawLayer raw;
  CellIndex index(geometry.num_grid_cells());
  const double inverse_size = 1.0 / geometry.cell_size;
  for (const Eigen::Vector3d& p : points) {
    // Points lie inside the box (p >= origin, so truncation is floor);
    // min() keeps rounding at the max face inside.
    const Eigen::Vector3i ijk = ((p - origin) * inverse_size)
                                    .cast<int>()
                                    .cwiseMin(geometry.dims - Eigen::Vector3i::Ones());
    const int32_t slot = index.FindOrInsert(geometry.Key(ijk),
                                            static_cast<int32_t>(raw.keys.size()));
    if (slot == static_cast<int32_t>(raw.keys.size())) {
      raw.keys.push_back(geometry.Key(ijk));
      raw.moments.emplace_back();
    }
    raw.moments[static_cast<size_t>(slot)].Add(p - centre);
  }
  return raw;
}

// Cells of a layer whose edge is `ratio` times the finer layer's: each fine
// cell (i, j, k) lies inside coarse cell (i, j, k) / ratio.
RawLayer Aggregate(const RawLayer& fine,
                   const LayerGeometry& fine_geometry,
                   const LayerGeometry& coarse_geometry,
                   int ratio) {
  RawLayer raw;
  CellIndex index(coarse_geometry.num_grid_cells());
  const int64_t dx = fine_geometry.dims.x();
  const int64_t dy = fine_geometry.dims.y();
  for (size_t i = 0; i < fine.keys.size(); ++i) {
    const int64_t key = fine.keys[i];
    const Eigen::Vector3i fine_ijk(static_cast<int>(key % dx),
                                   static_cast<int>((key / dx) % dy),
                                   static_cast<int>(key / (dx * dy)));
    const int64_t coarse_key = coarse_geometry.Key(fine_ijk / ratio);
    const int32_t slot =
        index.FindOrInsert(coarse_key, static_cast<int32_t>(raw.keys.size()));
    if (slot == static_cast<int32_t>(raw.keys.size())) {
      raw.keys.push_back(coarse_key);
      raw.moments.emplace_back();
    }
    raw.moments[static_cast<size_t>(slot)].Merge(fine.moments[i]);
  }
  return raw;
}

// Generative process: mean (Eq. 2), unbiased covariance (Eq. 3), regularised.
NdtLayer FinishLayer(const RawLayer& raw,
                     const Eigen::Vector3d& origin,
                     const Eigen::Vector3d& centre,
                     const LayerGeometry& geometry,
                     const LayeredGridOptions& options,
                     LayerInfo* info) {
  std::vector<NdtCell> cells;
  std::vector<int64_t> keys;
  for (size_t i = 0; i < raw.keys.size(); ++i) {
    const Moments& m = raw.moments[i];
    if (m.count < options.min_points_per_cell) {
      ++info->sparse_cells;
      continue;
    }
    const double n = static_cast<double>(m.count);
    const Eigen::Vector3d mean = m.sum / n;
    const Eigen::Matrix3d outer = m.outer.selfadjointView<Eigen::Upper>();
    const Eigen::Matrix3d covariance = (outer - n * mean * mean.transpose()) / (n - 1.0);
    NdtCell cell;
    if (!MakeNdtCell(static_cast<int32_t>(m.count),
                     mean + centre,
                     covariance,
                     options.regularization,
                     &cell)) {
      ++info->degenerate_cells;
      continue;
    }
    cells.push_back(cell);
    keys.push_back(raw.keys[i]);
  }
  info->cell_size_m = geometry.cell_size;
  info->dims = geometry.dims;
  info->occupied_cells = cells.size();
  return NdtLayer(origin, geometry.cell_size, geometry.dims, std::move(cells), std::move(keys));
}

// The layers' integer cube root of q, or 0 when q is not a perfect cube.
int NestingRatio(int q) {
  const int r = static_cast<int>(std::lround(std::cbrt(static_cast<double>(q))));
  return r * r * r == q ? r : 0;
}

Eigen::Vector3d EffectiveExtent(const Eigen::Vector3d& extent) {
  return extent.cwiseMax(0.01 * extent.maxCoeff());
}

int NumLayers(const LayeredGridOptions& options, double volume) {
  if (options.finest_cell_size_m <= 0.0) return options.num_layers;
  const double f = options.finest_cell_size_m;
  const double n = std::log(volume / (f * f * f)) / std::log(options.division_constant);
  return std::max(1, static_cast<int>(std::ceil(n - 1e-9)));
}

}  // namespace

bool LayeredGridOptions::IsValid(std::string* error) const {
  MLNDT_OPTION_GE(division_constant, 2);
  MLNDT_OPTION_GE(num_layers, 1);
  MLNDT_OPTION_GE(max_num_layers, 1);
  MLNDT_OPTION_LE(max_num_layers, 16);
  MLNDT_OPTION_LE(num_layers, max_num_layers);
  MLNDT_OPTION_GE(finest_cell_size_m, 0.0);
  MLNDT_OPTION_GE(min_points_per_cell, 4);
  MLNDT_OPTION_GT(regularization.min_eigenvalue_ratio, 0.0);
  MLNDT_OPTION_LE(regularization.min_eigenvalue_ratio, 1.0);
  MLNDT_OPTION_GE(regularization.min_eigenvalue_m2, 0.0);
  return true;
}

std::vector<double> LayerCellSizes(const LayeredGridOptions& options,
                                   const Eigen::Vector3d& extent) {
  std::string error;
  if (!options.IsValid(&error) || !(extent.maxCoeff() > 0.0)) return {};
  const Eigen::Vector3d e = EffectiveExtent(extent);
  const double volume = e.prod();
  const int n = NumLayers(options, volume);
  std::vector<double> sizes;
  for (int i = 1; i <= n; ++i) {
    sizes.push_back(std::cbrt(volume / std::pow(options.division_constant, i)));
  }
  return sizes;
}

bool LayeredGrid::Build(const LayeredGridOptions& options,
                        const PointCloud& reference,
                        LayeredGrid* grid,
                        std::string* error) {
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
  const Eigen::Vector3d e = EffectiveExtent(extent);
  const double volume = e.prod();
  const int n = NumLayers(options, volume);
  if (n > options.max_num_layers) {
    std::ostringstream message;
    message << "finest_cell_size_m = " << options.finest_cell_size_m << " needs " << n
            << " layers over this cloud; max_num_layers is " << options.max_num_layers;
    *error = message.str();
    return false;
  }

  // Layer geometries, finest last. With nesting, k_i = k_n r^(n - i) exactly.
  const int q = options.division_constant;
  const int ratio = NestingRatio(q);
  std::vector<LayerGeometry> geometry(static_cast<size_t>(n));
  const double finest = std::cbrt(volume / std::pow(q, n));
  for (int i = n; i >= 1; --i) {
    LayerGeometry& g = geometry[static_cast<size_t>(i - 1)];
    g.cell_size = ratio > 0 ? finest * std::pow(ratio, n - i) : std::cbrt(volume / std::pow(q, i));
    const Eigen::Vector3d cells = (extent / g.cell_size).array().floor() + 1.0;
    if (cells.maxCoeff() > 1e6 || cells.prod() > 4e18) {
      *error = "layer " + std::to_string(i) + " would have too many cells (cell size " +
               std::to_string(g.cell_size) + " m)";
      return false;
    }
    g.dims = cells.cast<int>();
    if (ratio > 0 && i < n) {  // Coarse dims consistent with nesting.
      g.dims = (geometry[static_cast<size_t>(i)].dims.array() - 1) / ratio + 1;
    }
  }

  const Eigen::Vector3d origin = bounds.min();
  const Eigen::Vector3d centre = bounds.center();
  std::vector<NdtLayer> layers(static_cast<size_t>(n));
  std::vector<LayerInfo> info(static_cast<size_t>(n));
  RawLayer raw;
  for (int i = n; i >= 1; --i) {
    const size_t l = static_cast<size_t>(i - 1);
    if (i == n || ratio == 0) {
      raw = BinPoints(reference.points(), origin, centre, geometry[l]);
    } else {
      raw = Aggregate(raw, geometry[l + 1], geometry[l], ratio);
    }
    info[l].layer = i;
    layers[l] = FinishLayer(raw, origin, centre, geometry[l], options, &info[l]);
  }
  *grid = LayeredGrid(options, bounds, reference.size(), std::move(layers), std::move(info));
  return true;
}

LayeredGrid::LayeredGrid(const LayeredGridOptions& options,
                         const Eigen::AlignedBox3d& bounds,
                         size_t num_points,
                         std::vector<NdtLayer> layers,
                         std::vector<LayerInfo> info)
    : options_(options),
      bounds_(bounds),
      num_points_(num_points),
      layers_(std::move(layers)),
      info_(std::move(info)) {}

}  // namespace mlndt
