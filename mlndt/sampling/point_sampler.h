#pragma once

// Sampling of the source scan before registration.
//
// ML-NDT (Ulas & Temeltas 2013), Section 4.3: the points of the input scan
// that take part in the optimisation are either drawn uniformly at random
// (10-20 % of the scan suffices) or chosen by grid-based sampling (GBS): the
// scan is split into 1 m cells; a cell with more than 5 points gives 5 of
// them picked at random, a cell with 3 to 5 points gives all of them and a
// sparser cell gives none.
//
// Every random choice comes from std::mt19937_64(options.seed) with an
// unbiased bounded draw written here (no std::uniform_int_distribution), so
// the same input and options give the same output on every platform. The
// output order is deterministic: cells in order of first appearance in the
// input, points inside a cell (and RANDOM picks) in input order.

#include <cstddef>
#include <cstdint>
#include <string>

#include "mlndt/cloud/point_cloud.h"

namespace mlndt {

class EnumTable;
class OptionTable;

enum class SamplingMethod {
  ALL,             // Every input point, unchanged.
  RANDOM,          // Uniformly random subset without repetition.
  GBS,             // Grid-based sampling, ML-NDT Section 4.3.
  VOXEL_CENTROID,  // One centroid per occupied voxel.
};

// The names of SamplingMethod's values (enum_table.h).
const EnumTable& SamplingMethodTable();
const char* SamplingMethodToString(SamplingMethod method);
// Case-insensitive: "all", "random", "gbs", "voxel_centroid".
bool StringToSamplingMethod(std::string value, SamplingMethod* method);

// Largest GBS cell or voxel edge [m]: 10 km, far above any scan's extent;
// larger values (1e300) are typing errors, refused by IsValid.
constexpr double kMaxSamplingCellM = 1e4;

struct SamplingOptions {
  SamplingMethod method = SamplingMethod::GBS;

  // RANDOM: fraction of the input kept, in (0, 1]; the kept count is
  // round(random_fraction * n), at least 1. Used when random_count == 0.
  double random_fraction = 0.15;
  // RANDOM: exact number of points kept (capped at the input size) when > 0.
  size_t random_count = 0;

  // GBS: cell edge [m], in (0, kMaxSamplingCellM].
  double gbs_cell_size_m = 1.0;
  // GBS: a cell with more points than this gives this many, picked at
  // random; must be >= gbs_min_points_per_cell.
  int gbs_points_per_cell = 5;
  // GBS: a cell with fewer points than this gives none; must be >= 1. Cells
  // with gbs_min_points_per_cell..gbs_points_per_cell points give them all.
  int gbs_min_points_per_cell = 3;
  // GBS sample budget: when capping every cell at gbs_points_per_cell keeps
  // fewer than this many points, the cap is raised, the same for every
  // cell, to the smallest that keeps at least this many (or every point of
  // the cells that give any). The samples stay spread over the scanned
  // surface as evenly as the scan allows; a dense scan, whose capped cells
  // already give the budget, is sampled as the paper says. 0: off (the
  // default; docs/defaults.md says why). In [0, 1e8].
  int gbs_min_samples = 0;

  // VOXEL_CENTROID: voxel edge [m], in (0, kMaxSamplingCellM].
  double voxel_size_m = 0.5;

  // Seed of the std::mt19937_64 behind every random choice.
  uint64_t seed = 1;

  // Returns false and names the offending field in *error (may be null).
  // Every field is checked, whichever method is selected.
  bool IsValid(std::string* error) const;
};

// SamplingOptions's fields: name, unit, valid range and help (option_table.h).
const OptionTable& SamplingOptionsTable();

struct SamplingSummary {
  size_t input_points = 0;          // Points in the input cloud.
  size_t sampled_points = 0;        // Points written to the output.
  size_t occupied_cells = 0;        // GBS cells / voxels holding >= 1 point.
  size_t dropped_sparse_cells = 0;  // GBS: cells with too few points.
  size_t points_per_cell = 0;       // GBS: the cap applied to every cell.
  double time_s = 0;                // Wall time of SamplePoints [s].
};

// Samples `input` as `options` says. Returns false with *error naming the
// invalid option, "empty input", "non-finite point at index i" or a point too
// far from the origin for the cell size, and leaves *sampled empty.
// `sampled` must not be null; `summary` and `error` may be null.
bool SamplePoints(const SamplingOptions& options,
                  const PointCloud& input,
                  PointCloud* sampled,
                  SamplingSummary* summary,
                  std::string* error);

// Voxel-grid centroid downsampling (the same as method VOXEL_CENTROID): one
// point per occupied voxel of edge `voxel_size_m` [m] (finite, > 0; checked),
// the mean of that voxel's points, voxels in order of first appearance.
// Non-finite points (and points too far out for the voxel size) are skipped.
PointCloud VoxelDownsample(const PointCloud& input, double voxel_size_m);

}  // namespace mlndt
