#include "mlndt/grid/map_memory.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "mlndt/common/internal/farthest_point.h"
#include "mlndt/grid/cell_coverage.h"
#include "mlndt/grid/cell_index.h"
#include "mlndt/grid/ndt_cell.h"
#include "mlndt/grid/ndt_layer.h"

namespace mlndt {
namespace {

// The per-cell moments LayeredGrid::Build accumulates (count, sum, outer
// product: int64 + Vector3d + Matrix3d).
constexpr size_t kMomentsBytes =
    sizeof(int64_t) + sizeof(Eigen::Vector3d) + sizeof(Eigen::Matrix3d);

// Capacity of a std::vector after `n` push_backs from empty (libstdc++
// doubles from 1).
size_t PushBackCapacity(size_t n) {
  size_t capacity = n > 0 ? 1 : 0;
  while (capacity < n) capacity *= 2;
  return capacity;
}

// A CellIndex while it is filled: the dense table, or the hash table with
// the half-size table it was rehashed from.
size_t IndexPeakBytes(int64_t grid_cells, size_t keys) {
  const size_t bytes = CellIndex::EstimateBytes(grid_cells, keys);
  return grid_cells <= CellIndex::kMaxDenseCells ? bytes : bytes + bytes / 2;
}

struct Geometry {
  double cell_size = 0.0;
  Eigen::Vector3i dims = Eigen::Vector3i::Zero();
  int64_t grid_cells() const { return int64_t{dims.x()} * dims.y() * dims.z(); }
  int64_t Key(const Eigen::Vector3i& ijk) const {
    return ijk.x() +
           int64_t{dims.x()} * (ijk.y() + int64_t{dims.y()} * ijk.z());
  }
};

// The layer geometries of LayeredGrid::Build (layered_grid.cc), finest
// last, and the nesting ratio (0 when q is not a perfect cube). Kept in
// step with Build by tests/grid/map_memory_test.cc.
// `layers` > 0 overrides the layer count (the coverage rule's lower n).
bool LayerGeometries(const LayeredGridOptions& options,
                     const Eigen::Vector3d& extent,
                     int layers,
                     std::vector<Geometry>* geometry,
                     int* ratio,
                     std::string* error) {
  const Eigen::Vector3d e = extent.cwiseMax(0.01 * extent.maxCoeff());
  const double volume = e.prod();
  int n = options.num_layers;
  if (layers > 0) {
    n = layers;
  } else if (options.cell_size_m > 0.0) {
    n = 1;
  } else if (options.finest_cell_size_m > 0.0) {
    const double f = options.finest_cell_size_m;
    const double layers =
        std::log(volume / (f * f * f)) / std::log(options.division_constant);
    n = std::max(1, static_cast<int>(std::ceil(layers - 1e-9)));
  }
  if (n > options.max_num_layers) {
    *error =
        "finest_cell_size_m = " + std::to_string(options.finest_cell_size_m) +
        " needs " + std::to_string(n) +
        " layers over this cloud; max_num_layers is " +
        std::to_string(options.max_num_layers);
    return false;
  }
  const int q = options.division_constant;
  const int r =
      static_cast<int>(std::lround(std::cbrt(static_cast<double>(q))));
  *ratio = r * r * r == q ? r : 0;
  geometry->assign(static_cast<size_t>(n), Geometry());
  const double finest = std::cbrt(volume / std::pow(q, n));
  for (int i = n; i >= 1; --i) {
    Geometry& g = (*geometry)[static_cast<size_t>(i - 1)];
    g.cell_size = options.cell_size_m > 0.0 ? options.cell_size_m
                  : *ratio > 0              ? finest * std::pow(*ratio, n - i)
                               : std::cbrt(volume / std::pow(q, i));
    const Eigen::Vector3d cells = (extent / g.cell_size).array().floor() + 1.0;
    if (cells.maxCoeff() > 1e6 || cells.prod() > 4e18) {
      *error = "layer " + std::to_string(i) +
               " would have too many cells (cell size " +
               std::to_string(g.cell_size) + " m)";
      return false;
    }
    g.dims = cells.cast<int>();
    if (*ratio > 0 && i < n) {
      g.dims =
          ((*geometry)[static_cast<size_t>(i)].dims.array() - 1) / *ratio + 1;
    }
  }
  return true;
}

// The touched cells of one layer: their keys and point counts, in order of
// first appearance.
struct CellCounts {
  std::vector<int64_t> keys;
  std::vector<int32_t> counts;
  size_t index_bytes = 0;  // The CellIndex used to build them.
  size_t Bytes() const {
    return keys.capacity() * sizeof(int64_t) +
           counts.capacity() * sizeof(int32_t);
  }
};

// Adds `points` points to the cell `key` (a new cell when the index does
// not know it) and returns its position.
int32_t AddToCell(int64_t key,
                  int32_t points,
                  CellIndex* index,
                  CellCounts* cells) {
  const int32_t slot =
      index->FindOrInsert(key, static_cast<int32_t>(cells->keys.size()));
  if (slot == static_cast<int32_t>(cells->keys.size())) {
    cells->keys.push_back(key);
    cells->counts.push_back(0);
  }
  cells->counts[static_cast<size_t>(slot)] += points;
  return slot;
}

// Bytes the counting tables will hold once they have room for 2 * touched
// cells: checked each time the number of touched cells reaches a power of
// two, before the tables grow.
size_t CountingBytesAfterGrowth(int64_t grid_cells, size_t touched) {
  return IndexPeakBytes(grid_cells, 2 * touched) +
         2 * touched * (sizeof(int64_t) + sizeof(int32_t));
}

// Counts the cells the points fall into, with the same arithmetic as
// layered_grid.cc's BinPoints. False (with *error) when `budget` > 0 and
// the tables would pass it.
bool CountPoints(const std::vector<Eigen::Vector3d>& points,
                 const Eigen::Vector3d& origin,
                 const Geometry& geometry,
                 size_t budget,
                 CellCounts* cells,
                 std::string* error) {
  const double inverse_size = 1.0 / geometry.cell_size;
  const Eigen::Vector3i max_ijk = geometry.dims - Eigen::Vector3i::Ones();
  CellIndex index(geometry.grid_cells());
  // Consecutive scan points often share a cell: remember the last one.
  int64_t last_key = -1;
  int32_t last_slot = -1;
  for (const Eigen::Vector3d& p : points) {
    const Eigen::Vector3i ijk =
        ((p - origin) * inverse_size).cast<int>().cwiseMin(max_ijk);
    const int64_t key = geometry.Key(ijk);
    if (key == last_key) {
      ++cells->counts[static_cast<size_t>(last_slot)];
      continue;
    }
    const size_t touched = cells->keys.size();
    if (budget > 0 && touched >= 1024 && (touched & (touched - 1)) == 0 &&
        CountingBytesAfterGrowth(geometry.grid_cells(), touched) > budget) {
      *error = "counting the cells of the map would need more than " +
               FormatBytes(static_cast<double>(budget)) + " besides the cloud";
      return false;
    }
    last_slot = AddToCell(key, 1, &index, cells);
    last_key = key;
  }
  cells->index_bytes = index.MemoryBytes();
  return true;
}

// The cells of the coarser layer: fine cell (i, j, k) lies in coarse cell
// (i, j, k) / ratio (layered_grid.cc's Aggregate).
CellCounts Aggregate(const CellCounts& fine,
                     const Geometry& fine_geometry,
                     const Geometry& coarse_geometry,
                     int ratio) {
  CellCounts coarse;
  CellIndex index(coarse_geometry.grid_cells());
  const int64_t dx = fine_geometry.dims.x();
  const int64_t dy = fine_geometry.dims.y();
  for (size_t i = 0; i < fine.keys.size(); ++i) {
    const int64_t key = fine.keys[i];
    const Eigen::Vector3i fine_ijk(static_cast<int>(key % dx),
                                   static_cast<int>((key / dx) % dy),
                                   static_cast<int>(key / (dx * dy)));
    AddToCell(
        coarse_geometry.Key(fine_ijk / ratio), fine.counts[i], &index, &coarse);
  }
  coarse.index_bytes = index.MemoryBytes();
  return coarse;
}

std::string NeedsMessage(const std::string& what,
                         size_t cloud_bytes,
                         size_t bytes,
                         size_t limit) {
  return what + ": the cloud (" +
         FormatBytes(static_cast<double>(cloud_bytes)) + ") plus " +
         FormatBytes(static_cast<double>(bytes)) + " to build the map = " +
         FormatBytes(static_cast<double>(cloud_bytes + bytes)) +
         " exceeds the memory limit of " +
         FormatBytes(static_cast<double>(limit));
}

// The reference cloud can be binned: not empty, finite, with a volume.
bool CheckCloud(const PointCloud& cloud,
                Eigen::AlignedBox3d* bounds,
                std::string* error) {
  if (cloud.empty()) {
    *error = "the reference cloud is empty";
    return false;
  }
  if (!AllFinite(cloud)) {
    *error = "the reference cloud has non-finite points";
    return false;
  }
  const Eigen::AlignedBox3d box = BoundingBox(cloud);
  *bounds =
      Eigen::AlignedBox3d(box.min().array() + 0.0, box.max().array() + 0.0);
  if (!(bounds->sizes().maxCoeff() > 0.0)) {
    *error = "all reference points coincide: the bounding box has no volume";
    return false;
  }
  return true;
}

// 1. From the geometry alone: binning holds a key and a slot per point
// and the finest layer's dense table; the map holds every dense table.
size_t GeometryPeakBytes(const MapMemoryEstimate& estimate, size_t num_points) {
  size_t dense_tables = 0;
  for (const LayerMemoryEstimate& layer : estimate.layers) {
    if (layer.dense_index) {
      dense_tables += CellIndex::EstimateBytes(layer.grid_cells, 0);
    }
  }
  const LayerMemoryEstimate& finest = estimate.layers.back();
  const size_t binning =
      num_points * (sizeof(int64_t) + sizeof(int32_t)) +
      (finest.dense_index ? CellIndex::EstimateBytes(finest.grid_cells, 0) : 0);
  return std::max(binning, dense_tables);
}

// 2. Counts the cells of every layer (finest first); sets the touched and
// kept cells and the bytes of every layer and the counting peak.
bool CountLayerCells(const LayeredGridOptions& options,
                     const PointCloud& cloud,
                     const Eigen::Vector3d& origin,
                     const std::vector<Geometry>& geometry,
                     int ratio,
                     size_t budget,
                     MapMemoryEstimate* estimate,
                     std::string* error) {
  const int n = static_cast<int>(geometry.size());
  std::vector<CellCounts> counts(static_cast<size_t>(n));
  size_t counting_peak = 0;
  for (int i = n; i >= 1; --i) {
    const size_t l = static_cast<size_t>(i - 1);
    if (i == n || ratio == 0) {
      if (!CountPoints(
              cloud.points(), origin, geometry[l], budget, &counts[l], error)) {
        return false;
      }
    } else {
      counts[l] = Aggregate(counts[l + 1], geometry[l + 1], geometry[l], ratio);
    }
    size_t alive = counts[l].Bytes() + counts[l].index_bytes;
    if (i < n) alive += counts[l + 1].Bytes();
    counting_peak = std::max(counting_peak, alive);
    // Keep only what the next layer needs.
    if (i < n) counts[l + 1].keys = std::vector<int64_t>();
  }
  estimate->counting_bytes = counting_peak;
  for (int i = 1; i <= n; ++i) {
    LayerMemoryEstimate& layer = estimate->layers[static_cast<size_t>(i - 1)];
    const std::vector<int32_t>& c = counts[static_cast<size_t>(i - 1)].counts;
    layer.touched_cells = c.size();
    layer.kept_cells = static_cast<size_t>(
        std::count_if(c.begin(), c.end(), [&](int32_t points) {
          return points >= options.min_points_per_cell;
        }));
    layer.bytes = sizeof(NdtLayer) +
                  layer.kept_cells * (sizeof(NdtCell) + sizeof(int64_t)) +
                  CellIndex::EstimateBytes(layer.grid_cells, layer.kept_cells);
  }
  return true;
}

// 3. The build's peak, phase by phase (layered_grid.cc), finest layer first.
size_t BuildPeakBytes(const MapMemoryEstimate& estimate,
                      size_t num_points,
                      int ratio) {
  const int n = static_cast<int>(estimate.layers.size());
  size_t finished =
      static_cast<size_t>(n) * (sizeof(NdtLayer) + sizeof(LayerInfo));
  size_t peak = 0;
  size_t raw_bytes = 0;  // The raw layer (keys, moments) carried over.
  for (int i = n; i >= 1; --i) {
    const LayerMemoryEstimate& layer =
        estimate.layers[static_cast<size_t>(i - 1)];
    const size_t r = layer.touched_cells;
    size_t new_raw = 0;
    if (i == n || ratio == 0) {  // BinPoints, while the old raw is alive.
      const size_t binning_peak =
          num_points * (sizeof(int64_t) + sizeof(int32_t)) +
          PushBackCapacity(r) * 2 * sizeof(int64_t) +
          IndexPeakBytes(layer.grid_cells, r) + r * kMomentsBytes;
      peak = std::max(peak, finished + raw_bytes + binning_peak);
      new_raw = PushBackCapacity(r) * sizeof(int64_t) + r * kMomentsBytes;
    } else {  // Aggregate from the finer raw layer.
      new_raw = PushBackCapacity(r) * (sizeof(int64_t) + kMomentsBytes);
      peak = std::max(
          peak,
          finished + raw_bytes + new_raw + IndexPeakBytes(layer.grid_cells, r));
    }
    raw_bytes = new_raw;
    // FinishLayer: a candidate cell and an outcome per raw cell, the kept
    // cells and keys, then the layer's own index.
    const size_t k = layer.kept_cells;
    peak = std::max(peak,
                    finished + raw_bytes + r * (sizeof(NdtCell) + 1) +
                        k * (sizeof(NdtCell) + sizeof(int64_t)) +
                        IndexPeakBytes(layer.grid_cells, k));
    finished += layer.bytes;
  }
  return peak;
}

}  // namespace

std::string FormatBytes(double bytes) {
  char text[64];
  if (bytes >= 1e9) {
    std::snprintf(text, sizeof(text), "%.2f GB", bytes / 1e9);
  } else if (bytes >= 1e6) {
    std::snprintf(text, sizeof(text), "%.1f MB", bytes / 1e6);
  } else if (bytes >= 1e3) {
    std::snprintf(text, sizeof(text), "%.1f kB", bytes / 1e3);
  } else {
    std::snprintf(text, sizeof(text), "%.0f B", bytes);
  }
  return text;
}

// LayeredGrid::Build's coverage rule (layered_grid.cc, BinFinestLayer):
// with n derived and min_covered_fraction > 0, one layer fewer while too
// few points lie in finest cells of >= min_points_per_cell points.
bool ApplyCoverageRule(const LayeredGridOptions& options,
                       const PointCloud& cloud,
                       const Eigen::AlignedBox3d& bounds,
                       std::vector<Geometry>* geometry,
                       int* ratio,
                       std::string* error) {
  if (!(options.finest_cell_size_m > 0.0 && options.cell_size_m == 0.0 &&
        options.min_covered_fraction > 0.0)) {
    return true;
  }
  while (geometry->size() > 1) {
    CellCounts cells;
    if (!CountPoints(
            cloud.points(), bounds.min(), geometry->back(), 0, &cells, error)) {
      return false;
    }
    const std::vector<int64_t> counts(cells.counts.begin(), cells.counts.end());
    if (CoveredPointFraction(counts, options.min_points_per_cell) >=
        options.min_covered_fraction) {
      return true;
    }
    const int n = static_cast<int>(geometry->size()) - 1;
    if (!LayerGeometries(options, bounds.sizes(), n, geometry, ratio, error)) {
      return false;
    }
  }
  return true;
}

bool EstimateMapMemory(const LayeredGridOptions& options,
                       const PointCloud& cloud,
                       size_t max_total_bytes,
                       MapMemoryEstimate* estimate,
                       std::string* error) {
  CHECK(estimate != nullptr);
  CHECK(error != nullptr);
  *estimate = MapMemoryEstimate();
  if (!options.IsValid(error)) return false;
  Eigen::AlignedBox3d bounds;
  if (!CheckCloud(cloud, &bounds, error)) return false;
  std::vector<Geometry> geometry;
  int ratio = 0;
  if (!LayerGeometries(options, bounds.sizes(), 0, &geometry, &ratio, error)) {
    if (error->find("layers over this cloud") != std::string::npos) {
      *error += " (" +
                internal::DescribeFarthestPoint(cloud.points(),
                                                bounds.sizes().maxCoeff()) +
                ")";
    }
    return false;
  }
  if (!ApplyCoverageRule(options, cloud, bounds, &geometry, &ratio, error)) {
    return false;
  }
  const int n = static_cast<int>(geometry.size());
  estimate->cloud_bytes = cloud.points().capacity() * sizeof(Eigen::Vector3d);
  estimate->layers.resize(static_cast<size_t>(n));
  for (int i = 1; i <= n; ++i) {
    LayerMemoryEstimate& layer = estimate->layers[static_cast<size_t>(i - 1)];
    const Geometry& g = geometry[static_cast<size_t>(i - 1)];
    layer.layer = i;
    layer.cell_size_m = g.cell_size;
    layer.dims = g.dims;
    layer.grid_cells = g.grid_cells();
    layer.dense_index = g.grid_cells() <= CellIndex::kMaxDenseCells;
  }
  const size_t limit = max_total_bytes;
  const size_t budget = limit > estimate->cloud_bytes
                            ? limit - estimate->cloud_bytes
                            : (limit > 0 ? 1 : 0);
  estimate->build_peak_bytes = GeometryPeakBytes(*estimate, cloud.size());
  if (limit > 0 && estimate->total_bytes() > limit) {
    *error = NeedsMessage("the map's geometry alone",
                          estimate->cloud_bytes,
                          estimate->build_peak_bytes,
                          limit);
    estimate->exceeds_limit = true;
    return false;
  }
  if (!CountLayerCells(options,
                       cloud,
                       bounds.min(),
                       geometry,
                       ratio,
                       budget,
                       estimate,
                       error)) {
    estimate->exceeds_limit = true;  // Only the budget stops the count.
    return false;
  }
  estimate->map_bytes =
      sizeof(LayeredGrid) + static_cast<size_t>(n) * sizeof(LayerInfo);
  for (const LayerMemoryEstimate& layer : estimate->layers) {
    estimate->map_bytes += layer.bytes;
  }
  estimate->build_peak_bytes = std::max(
      BuildPeakBytes(*estimate, cloud.size(), ratio), estimate->map_bytes);
  estimate->complete = true;
  if (limit > 0 && estimate->total_bytes() > limit) {
    *error = NeedsMessage("the map of " + std::to_string(n) + " layers",
                          estimate->cloud_bytes,
                          estimate->build_peak_bytes,
                          limit);
    estimate->exceeds_limit = true;
    return false;
  }
  return true;
}

}  // namespace mlndt
