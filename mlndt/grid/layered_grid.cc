#include "mlndt/grid/layered_grid.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>

#include "mlndt/common/enum_table.h"
#include "mlndt/common/internal/check_option.h"
#include "mlndt/common/internal/farthest_point.h"
#include "mlndt/common/option_table.h"
#include "mlndt/common/thread_budget.h"
#include "mlndt/grid/cell_coverage.h"

namespace mlndt {
namespace {

// Zeroth, first and second moments of a cell's points, relative to a fixed
// centre (the box centre) so that far-away coordinates keep their precision.
struct Moments {
  int64_t count = 0;    // Points.
  double weight = 0.0;  // Sum of weights (CoarseWeighting::FINEST_CELLS).
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d outer = Eigen::Matrix3d::Zero();

  void Add(const Eigen::Vector3d& d) {
    ++count;
    sum += d;
    // Upper triangle only, as selfadjointView<Upper>().rankUpdate(d) but
    // inlined (the Eigen call was a quarter of the build time): the same
    // products d(i) * d(j) and the same sums, so the same bits.
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j <= i; ++j) outer(j, i) += d(i) * d(j);
    }
  }
  void Merge(const Moments& other) {
    count += other.count;
    weight += other.weight;
    sum += other.sum;
    outer += other.outer;
  }
  // Scales the moments so that the cell weighs min(count, cap): as many
  // points as it has up to the cap, the cap beyond.
  void WeighCapped(int64_t cap) {
    const double n = static_cast<double>(count);
    const double w = static_cast<double>(std::min(count, cap));
    sum *= w / n;
    outer *= w / n;
    weight = w;
  }
};

// Cells of one layer that received points, in order of first appearance.
struct RawLayer {
  std::vector<int64_t> keys;
  std::vector<Moments> moments;
  bool weighted = false;  // Moments weighted per finest cell, not per point.
};

struct LayerGeometry {
  double cell_size = 0.0;
  Eigen::Vector3i dims = Eigen::Vector3i::Zero();
  int64_t num_grid_cells() const {
    return int64_t{dims.x()} * dims.y() * dims.z();
  }
  int64_t Key(const Eigen::Vector3i& ijk) const {
    return ijk.x() +
           int64_t{dims.x()} * (ijk.y() + int64_t{dims.y()} * ijk.z());
  }
};

// More threads than this are refused (libgomp fails far beyond it).
constexpr int kMaxThreads = 256;

// The reference cloud's bounding box, or false when a point is not finite:
// AllFinite and BoundingBox in one pass, split into `threads` chunks whose
// boxes are merged in chunk order. Min and max are exact, so the box does not
// depend on the chunking; + 0.0 turns a -0.0 bound into +0.0, the one thing
// an order of comparisons could change.
bool ScanBounds(const std::vector<Eigen::Vector3d>& points,
                int threads,
                Eigen::AlignedBox3d* bounds) {
  const int64_t n = static_cast<int64_t>(points.size());
  std::vector<Eigen::AlignedBox3d> boxes(static_cast<size_t>(threads));
  std::vector<char> finite(static_cast<size_t>(threads), 1);
#pragma omp parallel for num_threads(threads) \
    schedule(static, 1) if (threads > 1)
  for (int c = 0; c < threads; ++c) {
    Eigen::AlignedBox3d box;  // Constructed empty.
    bool chunk_finite = true;
    for (int64_t i = n * c / threads; i < n * (c + 1) / threads; ++i) {
      const Eigen::Vector3d& p = points[static_cast<size_t>(i)];
      chunk_finite = chunk_finite && p.allFinite();
      box.extend(p);
    }
    boxes[static_cast<size_t>(c)] = box;
    finite[static_cast<size_t>(c)] = chunk_finite;
  }
  Eigen::AlignedBox3d box;
  for (int c = 0; c < threads; ++c) {
    if (!finite[static_cast<size_t>(c)]) return false;
    box.extend(boxes[static_cast<size_t>(c)]);
  }
  *bounds =
      Eigen::AlignedBox3d(box.min().array() + 0.0, box.max().array() + 0.0);
  return true;
}

// Adds every point to the moments of its cell (point_slots[i] is the slot of
// point i, cell_points[s] the number of points of slot s). The slots are split
// into `threads` contiguous ranges of about equal point counts; each range
// walks all points in input order and takes its own, so every cell sums its
// points in the same order whatever the number of threads.
void AccumulateMoments(const std::vector<Eigen::Vector3d>& points,
                       const Eigen::Vector3d& centre,
                       const std::vector<int32_t>& point_slots,
                       const std::vector<int64_t>& cell_points,
                       int threads,
                       std::vector<Moments>* moments) {
  const int64_t n = static_cast<int64_t>(points.size());
  const int32_t num_cells = static_cast<int32_t>(cell_points.size());
  // Range r holds slots [first_slot[r], first_slot[r + 1]).
  std::vector<int32_t> first_slot(static_cast<size_t>(threads) + 1, num_cells);
  first_slot[0] = 0;
  int64_t points_before = 0;
  int range = 1;
  for (int32_t s = 0; s < num_cells && range < threads; ++s) {
    while (range < threads && points_before >= n * range / threads) {
      first_slot[static_cast<size_t>(range++)] = s;
    }
    points_before += cell_points[static_cast<size_t>(s)];
  }
#pragma omp parallel for num_threads(threads) \
    schedule(static, 1) if (threads > 1)
  for (int r = 0; r < threads; ++r) {
    const int32_t lo = first_slot[static_cast<size_t>(r)];
    const int32_t hi = first_slot[static_cast<size_t>(r) + 1];
    if (lo == hi) continue;
    for (int64_t i = 0; i < n; ++i) {
      const int32_t slot = point_slots[static_cast<size_t>(i)];
      if (slot >= lo && slot < hi) {
        (*moments)[static_cast<size_t>(slot)].Add(
            points[static_cast<size_t>(i)] - centre);
      }
    }
  }
}

// Splitting process for one layer on one thread: each point's key, slot
// (cells in order of first appearance) and moment update in one pass, in
// input order: the sums of BinPoints, without its per-point buffers.
RawLayer BinPointsSerial(const std::vector<Eigen::Vector3d>& points,
                         const Eigen::Vector3d& origin,
                         const Eigen::Vector3d& centre,
                         const LayerGeometry& geometry) {
  const double inverse_size = 1.0 / geometry.cell_size;
  const Eigen::Vector3i max_ijk = geometry.dims - Eigen::Vector3i::Ones();
  RawLayer raw;
  CellIndex index(geometry.num_grid_cells());
  // Consecutive scan points often share a cell: remember the last one.
  int64_t last_key = -1;
  size_t last_slot = 0;
  for (const Eigen::Vector3d& p : points) {
    // As in BinPoints: truncation is floor inside the box.
    const int64_t key = geometry.Key(
        ((p - origin) * inverse_size).cast<int>().cwiseMin(max_ijk));
    if (key != last_key) {
      const int32_t new_slot = static_cast<int32_t>(raw.keys.size());
      last_slot = static_cast<size_t>(index.FindOrInsert(key, new_slot));
      if (static_cast<int32_t>(last_slot) == new_slot) {
        raw.keys.push_back(key);
        raw.moments.emplace_back();
      }
      last_key = key;
    }
    raw.moments[last_slot].Add(p - centre);
  }
  return raw;
}

// Splitting process for one layer: every point goes to its cell. The cell
// keys of the points are computed in parallel, the slots (cells in order of
// first appearance) serially, the moments in parallel by cell.
RawLayer BinPoints(const std::vector<Eigen::Vector3d>& points,
                   const Eigen::Vector3d& origin,
                   const Eigen::Vector3d& centre,
                   const LayerGeometry& geometry,
                   int threads) {
  const int64_t n = static_cast<int64_t>(points.size());
  const double inverse_size = 1.0 / geometry.cell_size;
  const Eigen::Vector3i max_ijk = geometry.dims - Eigen::Vector3i::Ones();
  std::vector<int64_t> point_keys(static_cast<size_t>(n));
#pragma omp parallel for num_threads(threads) schedule(static) if (threads > 1)
  for (int64_t i = 0; i < n; ++i) {
    // Points lie inside the box (p >= origin, so truncation is floor);
    // min() keeps rounding at the max face inside.
    const Eigen::Vector3i ijk =
        ((points[static_cast<size_t>(i)] - origin) * inverse_size)
            .cast<int>()
            .cwiseMin(max_ijk);
    point_keys[static_cast<size_t>(i)] = geometry.Key(ijk);
  }

  RawLayer raw;
  std::vector<int32_t> point_slots(static_cast<size_t>(n));
  std::vector<int64_t> cell_points;
  CellIndex index(geometry.num_grid_cells());
  // Consecutive scan points often share a cell: remember the last one.
  int64_t last_key = -1;
  int32_t last_slot = -1;
  for (int64_t i = 0; i < n; ++i) {
    const int64_t key = point_keys[static_cast<size_t>(i)];
    if (key != last_key) {
      const int32_t new_slot = static_cast<int32_t>(raw.keys.size());
      last_slot = index.FindOrInsert(key, new_slot);
      if (last_slot == new_slot) {
        raw.keys.push_back(key);
        cell_points.push_back(0);
      }
      last_key = key;
    }
    point_slots[static_cast<size_t>(i)] = last_slot;
    ++cell_points[static_cast<size_t>(last_slot)];
  }
  raw.moments.resize(raw.keys.size());
  AccumulateMoments(
      points, centre, point_slots, cell_points, threads, &raw.moments);
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
  raw.weighted = fine.weighted;
  return raw;
}

// Generative process for one cell: mean (Eq. 2), unbiased covariance
// (Eq. 3), regularised (MakeNdtCell). False for a degenerate cell.
bool MakeCell(const Moments& m,
              bool weighted,
              const Eigen::Vector3d& centre,
              const CellRegularization& regularization,
              NdtCell* cell) {
  const double n = static_cast<double>(m.count);
  const Eigen::Matrix3d outer = m.outer.selfadjointView<Eigen::Upper>();
  Eigen::Vector3d mean;
  Eigen::Matrix3d covariance;
  if (weighted) {
    // The mixture of the finest cells, weighted as WeighCapped says;
    // n / (n - 1) makes it Eq. (3) when one finest cell fills the cell.
    mean = m.sum / m.weight;
    covariance = (outer / m.weight - mean * mean.transpose()) * (n / (n - 1.0));
  } else {
    mean = m.sum / n;
    covariance = (outer - n * mean * mean.transpose()) / (n - 1.0);
  }
  return MakeNdtCell(static_cast<int32_t>(m.count),
                     mean + centre,
                     covariance,
                     regularization,
                     cell);
}

// The layer from its raw cells: the cells with enough points are computed
// (in parallel), then kept in raw order; sparse and degenerate ones counted.
NdtLayer FinishLayer(const RawLayer& raw,
                     const Eigen::Vector3d& origin,
                     const Eigen::Vector3d& centre,
                     const LayerGeometry& geometry,
                     const LayeredGridOptions& options,
                     int threads,
                     LayerInfo* info) {
  // Raw cells with enough points; only these get a cell (most raw cells of
  // a fine layer are sparse).
  std::vector<int32_t> dense;
  for (size_t i = 0; i < raw.keys.size(); ++i) {
    if (raw.moments[i].count < options.min_points_per_cell) {
      ++info->sparse_cells;
    } else {
      dense.push_back(static_cast<int32_t>(i));
    }
  }
  const int64_t num_dense = static_cast<int64_t>(dense.size());
  std::vector<NdtCell> cells(dense.size());
  std::vector<char> made(dense.size());
  // Per cell, in its own slot: the thread count changes no bit.
  const int cell_threads =
      ThreadsFor(num_dense, kMinMapCellsPerThread, threads);
#pragma omp parallel for num_threads(cell_threads) \
    schedule(static) if (cell_threads > 1)
  for (int64_t j = 0; j < num_dense; ++j) {
    const size_t i = static_cast<size_t>(dense[static_cast<size_t>(j)]);
    made[static_cast<size_t>(j)] = MakeCell(raw.moments[i],
                                            raw.weighted,
                                            centre,
                                            options.regularization,
                                            &cells[static_cast<size_t>(j)]);
  }
  std::vector<int64_t> keys;
  keys.reserve(
      static_cast<size_t>(std::count(made.begin(), made.end(), char{1})));
  size_t kept = 0;
  for (size_t j = 0; j < dense.size(); ++j) {
    if (!made[j]) {
      ++info->degenerate_cells;
      continue;
    }
    if (kept != j) cells[kept] = cells[j];
    keys.push_back(raw.keys[static_cast<size_t>(dense[j])]);
    ++kept;
  }
  cells.resize(kept);
  cells.shrink_to_fit();  // The capacity is MemoryBytes()'s.
  info->cell_size_m = geometry.cell_size;
  info->dims = geometry.dims;
  info->occupied_cells = cells.size();
  return NdtLayer(origin,
                  geometry.cell_size,
                  geometry.dims,
                  std::move(cells),
                  std::move(keys));
}

// The layers' integer cube root of q, or 0 when q is not a perfect cube.
int NestingRatio(int q) {
  const int r =
      static_cast<int>(std::lround(std::cbrt(static_cast<double>(q))));
  return r * r * r == q ? r : 0;
}

Eigen::Vector3d EffectiveExtent(const Eigen::Vector3d& extent) {
  return extent.cwiseMax(0.01 * extent.maxCoeff());
}

int NumLayers(const LayeredGridOptions& options, double volume) {
  if (options.cell_size_m > 0.0) return 1;
  if (options.finest_cell_size_m <= 0.0) return options.num_layers;
  const double f = options.finest_cell_size_m;
  const double n =
      std::log(volume / (f * f * f)) / std::log(options.division_constant);
  return std::max(1, static_cast<int>(std::ceil(n - 1e-9)));
}

}  // namespace

const EnumTable& CoarseWeightingTable() {
  static const EnumTable table({
      {static_cast<int>(CoarseWeighting::POINTS), "POINTS"},
      {static_cast<int>(CoarseWeighting::FINEST_CELLS), "FINEST_CELLS"},
  });
  return table;
}

const char* CoarseWeightingToString(CoarseWeighting weighting) {
  return EnumToString(CoarseWeightingTable(), weighting);
}

bool StringToCoarseWeighting(std::string value, CoarseWeighting* weighting) {
  return StringToEnum(CoarseWeightingTable(), std::move(value), weighting);
}

const OptionTable& LayeredGridOptionsTable() {
  using S = LayeredGridOptions;
  static const OptionTable table =
      OptionTableBuilder<S>("LayeredGridOptions")
          .Int("division_constant",
               &S::division_constant,
               Closed(2, 512),
               "q: layer i has about q^i cells over the bounding box.")
          .Int("num_layers",
               &S::num_layers,
               Closed(1, 16),
               "n, used when finest_cell_size_m == 0 (<= max_num_layers).")
          .Double("finest_cell_size_m",
                  &S::finest_cell_size_m,
                  "m",
                  ClosedOrZero(1e-3, 1e5),
                  "When > 0, n is the smallest layer count whose finest cell "
                  "is <= this.")
          .Double("min_covered_fraction",
                  &S::min_covered_fraction,
                  "",
                  Closed(0.0, 1.0),
                  "With n derived from finest_cell_size_m: n is lowered while "
                  "fewer than this fraction of the reference points lie in "
                  "finest cells of >= min_points_per_cell points; 0 = off.")
          .Double("cell_size_m",
                  &S::cell_size_m,
                  "m",
                  ClosedOrZero(1e-3, 1e5),
                  "When > 0, one layer of cells of exactly this edge (the "
                  "conventional NDT grid).")
          .Int("max_num_layers",
               &S::max_num_layers,
               Closed(1, 16),
               "Upper bound on n.")
          .Int("min_points_per_cell",
               &S::min_points_per_cell,
               Closed(4, 1000000),
               "A cell keeps a distribution with at least this many points.")
          .Struct("regularization",
                  &S::regularization,
                  CellRegularizationTable(),
                  "Covariance regularisation (ndt_cell.h).")
          .Enum("coarse_weighting",
                &S::coarse_weighting,
                CoarseWeightingTable(),
                "Weights of the points in the coarse layers' moments "
                "(finest_cells: every finest cell alike).")
          .Validator(&S::IsValid)
          .Build();
  return table;
}

bool LayeredGridOptions::IsValid(std::string* error) const {
  if (!LayeredGridOptionsTable().Check(*this, error)) return false;
  MLNDT_OPTION_IN_RANGE(num_layers, 1, max_num_layers);
  return true;
}

bool operator==(const LayeredGridOptions& a, const LayeredGridOptions& b) {
  return a.division_constant == b.division_constant &&
         a.num_layers == b.num_layers &&
         a.finest_cell_size_m == b.finest_cell_size_m &&
         a.min_covered_fraction == b.min_covered_fraction &&
         a.cell_size_m == b.cell_size_m &&
         a.max_num_layers == b.max_num_layers &&
         a.min_points_per_cell == b.min_points_per_cell &&
         a.regularization.min_eigenvalue_ratio ==
             b.regularization.min_eigenvalue_ratio &&
         a.regularization.min_eigenvalue_m2 ==
             b.regularization.min_eigenvalue_m2 &&
         a.regularization.line_ratio == b.regularization.line_ratio &&
         a.regularization.plane_ratio == b.regularization.plane_ratio &&
         a.regularization.in_plane_variance_scale ==
             b.regularization.in_plane_variance_scale &&
         a.coarse_weighting == b.coarse_weighting;
}

LayeredGridOptions PaperLayeredGridOptions() {
  LayeredGridOptions options;
  options.finest_cell_size_m = 0.0;
  options.num_layers = 4;
  options.coarse_weighting = CoarseWeighting::POINTS;
  options.regularization = WholeCovarianceRegularization();
  return options;
}

std::vector<double> LayerCellSizes(const LayeredGridOptions& options,
                                   const Eigen::Vector3d& extent) {
  std::string error;
  if (!options.IsValid(&error) || !(extent.maxCoeff() > 0.0)) return {};
  const Eigen::Vector3d e = EffectiveExtent(extent);
  const double volume = e.prod();
  const int n = NumLayers(options, volume);
  if (options.cell_size_m > 0.0) return {options.cell_size_m};
  std::vector<double> sizes;
  for (int i = 1; i <= n; ++i) {
    sizes.push_back(std::cbrt(volume / std::pow(options.division_constant, i)));
  }
  return sizes;
}

namespace {

// The layers' cell sizes and dimensions, finest last. With nesting,
// k_i = k_n r^(n - i) exactly. False with *error when a layer would have
// too many cells.
bool LayerGeometries(const LayeredGridOptions& options,
                     const Eigen::Vector3d& extent,
                     double volume,
                     int n,
                     std::vector<LayerGeometry>* geometry_out,
                     std::string* error) {
  const int q = options.division_constant;
  const int ratio = NestingRatio(q);
  std::vector<LayerGeometry> geometry(static_cast<size_t>(n));
  const double finest = std::cbrt(volume / std::pow(q, n));
  for (int i = n; i >= 1; --i) {
    LayerGeometry& g = geometry[static_cast<size_t>(i - 1)];
    g.cell_size = options.cell_size_m > 0.0 ? options.cell_size_m
                  : ratio > 0               ? finest * std::pow(ratio, n - i)
                              : std::cbrt(volume / std::pow(q, i));
    const Eigen::Vector3d cells = (extent / g.cell_size).array().floor() + 1.0;
    if (cells.maxCoeff() > 1e6 || cells.prod() > 4e18) {
      *error = "layer " + std::to_string(i) +
               " would have too many cells (cell size " +
               std::to_string(g.cell_size) + " m)";
      return false;
    }
    g.dims = cells.cast<int>();
    if (ratio > 0 && i < n) {  // Coarse dims consistent with nesting.
      g.dims = (geometry[static_cast<size_t>(i)].dims.array() - 1) / ratio + 1;
    }
  }
  *geometry_out = std::move(geometry);
  return true;
}

// Splitting process for one layer, serial or on `threads` threads (the same
// cells and sums either way).
RawLayer BinLayer(const std::vector<Eigen::Vector3d>& points,
                  const Eigen::Vector3d& origin,
                  const Eigen::Vector3d& centre,
                  const LayerGeometry& geometry,
                  int threads) {
  return threads == 1 ? BinPointsSerial(points, origin, centre, geometry)
                      : BinPoints(points, origin, centre, geometry, threads);
}

// The fraction of the points in cells of `raw` with >= min_points points.
double CoveredFraction(const RawLayer& raw, int min_points) {
  std::vector<int64_t> counts;
  counts.reserve(raw.moments.size());
  for (const Moments& m : raw.moments) counts.push_back(m.count);
  return CoveredPointFraction(counts, min_points);
}

// The geometry of the *n layers and the finest layer's cells. With n derived
// from finest_cell_size_m and min_covered_fraction > 0, *n is lowered (the
// finest cell grows by cbrt(q)) while too few points lie in finest cells
// that can hold a distribution (cell_coverage.h); the binning that decides is
// the one the map keeps, so a cloud that passes pays nothing.
bool BinFinestLayer(const LayeredGridOptions& options,
                    const std::vector<Eigen::Vector3d>& points,
                    const Eigen::AlignedBox3d& bounds,
                    int threads,
                    int* n,
                    std::vector<LayerGeometry>* geometry,
                    RawLayer* raw,
                    std::string* error) {
  const Eigen::Vector3d extent = bounds.sizes();
  const double volume = EffectiveExtent(extent).prod();
  const bool derived = options.finest_cell_size_m > 0.0 &&
                       options.cell_size_m == 0.0 &&
                       options.min_covered_fraction > 0.0;
  while (true) {
    if (!LayerGeometries(options, extent, volume, *n, geometry, error)) {
      return false;
    }
    *raw = BinLayer(
        points, bounds.min(), bounds.center(), geometry->back(), threads);
    if (!derived || *n == 1 ||
        CoveredFraction(*raw, options.min_points_per_cell) >=
            options.min_covered_fraction) {
      return true;
    }
    --*n;
  }
}

}  // namespace

bool LayeredGrid::Build(const LayeredGridOptions& options,
                        const PointCloud& reference,
                        LayeredGrid* grid,
                        std::string* error) {
  return Build(options, reference, 1, grid, error);
}

bool LayeredGrid::Build(const LayeredGridOptions& options,
                        const PointCloud& reference,
                        int num_threads,
                        LayeredGrid* grid,
                        std::string* error) {
  if (!options.IsValid(error)) return false;
  if (num_threads < 1 || num_threads > kMaxThreads) {
    *error = "invalid num_threads = " + std::to_string(num_threads) +
             "; it must be in [1, " + std::to_string(kMaxThreads) + "]";
    return false;
  }
  if (reference.empty()) {
    *error = "the reference cloud is empty";
    return false;
  }
  // Small clouds are built on one thread (thread_budget.h); the map's bits
  // do not depend on the count.
  num_threads = ThreadsFor(static_cast<int64_t>(reference.size()),
                           kMinMapPointsPerThread,
                           num_threads);
  Eigen::AlignedBox3d bounds;
  if (!ScanBounds(reference.points(), num_threads, &bounds)) {
    *error = "the reference cloud has non-finite points";
    return false;
  }
  const Eigen::Vector3d extent = bounds.sizes();
  if (!(extent.maxCoeff() > 0.0)) {
    *error = "all reference points coincide: the bounding box has no volume";
    return false;
  }
  const Eigen::Vector3d e = EffectiveExtent(extent);
  int n = NumLayers(options, e.prod());
  if (n > options.max_num_layers) {
    std::ostringstream message;
    message << "finest_cell_size_m = " << options.finest_cell_size_m
            << " needs " << n << " layers over this cloud; max_num_layers is "
            << options.max_num_layers << " ("
            << internal::DescribeFarthestPoint(reference.points(),
                                               extent.maxCoeff())
            << ")";
    *error = message.str();
    return false;
  }

  const int ratio = NestingRatio(options.division_constant);
  std::vector<LayerGeometry> geometry;
  RawLayer raw;
  if (!BinFinestLayer(options,
                      reference.points(),
                      bounds,
                      num_threads,
                      &n,
                      &geometry,
                      &raw,
                      error)) {
    return false;
  }

  const Eigen::Vector3d origin = bounds.min();
  const Eigen::Vector3d centre = bounds.center();
  std::vector<NdtLayer> layers(static_cast<size_t>(n));
  std::vector<LayerInfo> info(static_cast<size_t>(n));
  for (int i = n; i >= 1; --i) {
    const size_t l = static_cast<size_t>(i - 1);
    if (i < n && ratio == 0) {
      raw = BinLayer(
          reference.points(), origin, centre, geometry[l], num_threads);
    } else if (i < n) {
      if (options.coarse_weighting == CoarseWeighting::FINEST_CELLS &&
          !raw.weighted) {
        for (Moments& m : raw.moments)
          m.WeighCapped(options.min_points_per_cell);
        raw.weighted = true;
      }
      raw = Aggregate(raw, geometry[l + 1], geometry[l], ratio);
    }
    info[l].layer = i;
    layers[l] = FinishLayer(
        raw, origin, centre, geometry[l], options, num_threads, &info[l]);
  }
  *grid = LayeredGrid(
      options, bounds, reference.size(), std::move(layers), std::move(info));
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

size_t LayeredGrid::MemoryBytes() const {
  size_t bytes = sizeof(LayeredGrid) +
                 (layers_.capacity() - layers_.size()) * sizeof(NdtLayer) +
                 info_.capacity() * sizeof(LayerInfo);
  for (const NdtLayer& layer : layers_) bytes += layer.MemoryBytes();
  return bytes;
}

}  // namespace mlndt
