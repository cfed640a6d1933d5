#pragma once

// The layered NDT map of ML-NDT (Section 4, Table 1).
//
// Splitting process: the reference scan's bounding box (volume V) is divided,
// for layer i = 1..n, into cubic cells of edge k_i = (V / q^i)^(1/3), with
// floor(extent / k_i) + 1 cells per axis (= ceil(extent / k_i) unless the
// division is exact, where the extra cell holds the points on the max face).
// Example from the paper: a 100 x 100 x 20 m box with q = 8 gives, on layer
// 2, 14.62 m cells in a 7 x 7 x 2 grid.
//
// The finest cell is sized from the data: n is the smallest layer count
// whose finest cell is <= finest_cell_size_m, lowered while fewer than
// min_covered_fraction of the points lie in finest cells that can hold a
// distribution (cell_coverage.h), so a sparse cloud gets cells it fills.
//
// Generative process: every cell with at least `min_points_per_cell` points
// (the paper: "more than 4") keeps its mean (Eq. 2), unbiased covariance
// (Eq. 3), regularised as in Section 4.1 (see ndt_cell.h), the inverse and
// the whitening matrix W.
//
// When q is a perfect cube (q = 8: the edge halves from one layer to the
// next), the cells nest and coarse layers are aggregated from the finest
// layer's moments instead of re-binning the points. Moments are accumulated
// relative to the box centre, so coordinates far from the origin (UTM,
// 4e6 m) keep their precision.
//
// With LayeredGridOptions::cell_size_m > 0 the map is one layer of cells of
// exactly that edge: the grid of the conventional NDT baseline (ndt/).

#include <string>
#include <vector>

#include "mlndt/cloud/point_cloud.h"
#include "mlndt/grid/ndt_layer.h"

namespace mlndt {

class EnumTable;
class OptionTable;

// How the points of a coarse cell are weighted in its mean and covariance.
enum class CoarseWeighting {
  POINTS,  // Every point alike (Eqs. 2-3).
  // Every finest-layer cell alike: the coarse cell is the mixture of its
  // finest cells' distributions, each weighing min(points,
  // min_points_per_cell) (a sparse cell counts its few points). A scanner
  // samples the ground near it far more densely than the scene farther out,
  // and those points travel with it; weighting the finest cells alike keeps
  // them from dominating the coarse cells. Needs nested layers (q a perfect
  // cube); POINTS otherwise.
  FINEST_CELLS,
};

// The names of CoarseWeighting's values (enum_table.h).
const EnumTable& CoarseWeightingTable();
const char* CoarseWeightingToString(CoarseWeighting weighting);
bool StringToCoarseWeighting(std::string value, CoarseWeighting* weighting);

// The library's map; PaperLayeredGridOptions() is the paper's (n = 4).
struct LayeredGridOptions {
  // q: layer i has about q^i cells over the bounding box. In [2, 512].
  int division_constant = 8;
  // n: number of layers. In [1, max_num_layers]. Ignored when
  // finest_cell_size_m > 0.
  int num_layers = 4;
  // When > 0, n is the smallest number of layers whose finest cell edge is
  // <= this [m] (docs/defaults.md: why 1.2 m). 0, or in [1e-3, 1e5].
  double finest_cell_size_m = 1.2;
  // With n derived from finest_cell_size_m: while fewer than this fraction
  // of the reference points lie in finest cells holding at least
  // min_points_per_cell points, n is lowered by one (the finest cell
  // grows by cbrt(q)), so a sparse cloud gets cells it can fill
  // (cell_coverage.h; docs/defaults.md). 0: off. In [0, 1].
  double min_covered_fraction = 0.5;
  // When > 0, the map has one layer of cubic cells of exactly this edge [m]
  // (the conventional NDT grid) and q, n and finest_cell_size_m are ignored.
  // 0, or in [1e-3, 1e5].
  double cell_size_m = 0.0;
  // Upper bound on n, derived or given. In [1, 16].
  int max_num_layers = 12;
  // A cell keeps a distribution when it holds at least this many points.
  // In [4, 1e6] (3 points always give a singular covariance).
  int min_points_per_cell = 5;
  // Covariance regularisation (ndt_cell.h). min_eigenvalue_ratio in
  // [1e-9, 1], min_eigenvalue_m2 in [0, 1e6].
  CellRegularization regularization;
  // Weights of the points in the coarse layers' moments (the finest layer
  // always weighs every point alike).
  CoarseWeighting coarse_weighting = CoarseWeighting::FINEST_CELLS;

  bool IsValid(std::string* error) const;
};

// LayeredGridOptions's fields: name, unit, valid range and help
// (option_table.h).
const OptionTable& LayeredGridOptionsTable();

// Equal when two option sets build the same map (for map caches).
bool operator==(const LayeredGridOptions& a, const LayeredGridOptions& b);
inline bool operator!=(const LayeredGridOptions& a,
                       const LayeredGridOptions& b) {
  return !(a == b);
}

// The paper's map: n = 4 layers over the bounding box (Section 4).
LayeredGridOptions PaperLayeredGridOptions();

// Per-layer facts, for reports.
struct LayerInfo {
  int layer = 0;             // 1-based layer index i.
  double cell_size_m = 0.0;  // k_i.
  Eigen::Vector3i dims = Eigen::Vector3i::Zero();
  size_t occupied_cells = 0;    // Cells holding >= min_points_per_cell points.
  size_t sparse_cells = 0;      // Cells with points but too few of them.
  size_t degenerate_cells = 0;  // Enough points, but no usable covariance.
};

class LayeredGrid {
 public:
  LayeredGrid() = default;

  // Builds the map of `reference`. Returns false with *error (and leaves
  // *grid unchanged) for invalid options, an empty cloud, non-finite points,
  // a cloud whose points all coincide or a map with too many cells.
  static bool Build(const LayeredGridOptions& options,
                    const PointCloud& reference,
                    LayeredGrid* grid,
                    std::string* error);
  // The same with `num_threads` OpenMP threads (>= 1) for the bounds scan,
  // the per-point cell keys, the per-cell moments and the per-cell
  // eigen-decompositions. The map is bit-identical for every value: each
  // cell still sums its points in input order, and cells keep their order of
  // first appearance. OpenMP's idle threads spin-wait by default: on a
  // loaded machine keep 1, or set OMP_WAIT_POLICY=passive.
  static bool Build(const LayeredGridOptions& options,
                    const PointCloud& reference,
                    int num_threads,
                    LayeredGrid* grid,
                    std::string* error);

  int num_layers() const { return static_cast<int>(layers_.size()); }
  // Layer i, 1-based as in the paper: layer(1) is the coarsest.
  const NdtLayer& layer(int i) const {
    return layers_.at(static_cast<size_t>(i - 1));
  }
  const std::vector<LayerInfo>& layer_info() const { return info_; }
  const LayeredGridOptions& options() const { return options_; }
  // The reference scan's bounding box.
  const Eigen::AlignedBox3d& bounds() const { return bounds_; }
  size_t num_points() const { return num_points_; }
  bool empty() const { return layers_.empty(); }

  // Heap and object bytes the map holds: every layer's MemoryBytes()
  // (cells, keys, cell index; see NdtLayer::MemoryBytes) plus this object,
  // the unused capacity of the layer vector and the per-layer infos. An
  // estimate of the allocation sizes, without the allocator's overhead.
  size_t MemoryBytes() const;

  // Assembles a grid from finished layers (used by the map file reader).
  LayeredGrid(const LayeredGridOptions& options,
              const Eigen::AlignedBox3d& bounds,
              size_t num_points,
              std::vector<NdtLayer> layers,
              std::vector<LayerInfo> info);

 private:
  LayeredGridOptions options_;
  Eigen::AlignedBox3d bounds_;
  size_t num_points_ = 0;
  std::vector<NdtLayer> layers_;
  std::vector<LayerInfo> info_;
};

// Cell edges k_1..k_n of the layers for a box of the given extent [m]; empty
// on invalid options. Degenerate extents (a flat cloud) are raised to 1 % of
// the largest extent so that V > 0.
std::vector<double> LayerCellSizes(const LayeredGridOptions& options,
                                   const Eigen::Vector3d& extent);

}  // namespace mlndt
