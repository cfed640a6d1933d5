#include "mlndt/sampling/point_sampler.h"

#include <glog/logging.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <sstream>
#include <utility>
#include <vector>

#include "mlndt/common/enum_table.h"
#include "mlndt/common/internal/check_option.h"
#include "mlndt/common/option_table.h"
#include "mlndt/sampling/voxel_key.h"

namespace mlndt {
namespace {

void SetError(const std::string& message, std::string* error) {
  if (error != nullptr) *error = message;
}

// Uniform integer in [0, n), n > 0, without modulo bias: draws below
// 2^64 mod n are rejected so that the accepted range is a multiple of n.
// Only the raw 64-bit output of the engine is used, which the standard
// fixes exactly, so results match on every platform.
uint64_t UniformBelow(uint64_t n, std::mt19937_64* rng) {
  DCHECK_GT(n, 0u);
  const uint64_t threshold = (0 - n) % n;  // == 2^64 mod n.
  while (true) {
    const uint64_t r = (*rng)();
    if (r >= threshold) return r % n;
  }
}

// Keeps `k` of the entries of *indices, chosen uniformly at random without
// repetition (partial Fisher-Yates), and sorts them ascending so that the
// output follows the input order. k <= indices->size().
void ChooseSubset(size_t k,
                  std::mt19937_64* rng,
                  std::vector<size_t>* indices) {
  const size_t n = indices->size();
  DCHECK_LE(k, n);
  if (k < n) {
    for (size_t i = 0; i < k; ++i) {
      const size_t j = i + static_cast<size_t>(UniformBelow(n - i, rng));
      std::swap((*indices)[i], (*indices)[j]);
    }
    indices->resize(k);
  }
  std::sort(indices->begin(), indices->end());
}

bool IsPositiveFinite(double value) {
  return std::isfinite(value) && value > 0.0;
}

void SampleRandom(const SamplingOptions& options,
                  const PointCloud& input,
                  PointCloud* sampled) {
  const size_t n = input.size();
  size_t k = options.random_count;
  if (k == 0) {
    k = static_cast<size_t>(
        std::llround(options.random_fraction * static_cast<double>(n)));
    k = std::max<size_t>(k, 1);
  }
  k = std::min(k, n);
  std::vector<size_t> indices(n);
  for (size_t i = 0; i < n; ++i) indices[i] = i;
  std::mt19937_64 rng(options.seed);
  ChooseSubset(k, &rng, &indices);
  sampled->Reserve(k);
  for (size_t i : indices) sampled->Add(input[i]);
}

// The per-cell cap of GBS: gbs_points_per_cell, raised to the smallest
// cap P at which sum_c min(n_c, P) over the cells that give points reaches
// min(gbs_min_samples, their points) (a water level: every cell gives P or
// all it has). The kept count grows monotonically with P: bisection.
size_t GbsCap(const SamplingOptions& options,
              const VoxelGroups& cells,
              size_t min_per_cell) {
  size_t cap = static_cast<size_t>(options.gbs_points_per_cell);
  if (options.gbs_min_samples <= 0) return cap;
  std::vector<size_t> counts;
  size_t available = 0;
  for (size_t c = 0; c < cells.num_voxels(); ++c) {
    if (cells.num_points(c) < min_per_cell) continue;
    counts.push_back(cells.num_points(c));
    available += counts.back();
  }
  const size_t target =
      std::min(available, static_cast<size_t>(options.gbs_min_samples));
  auto kept = [&counts](size_t p) {
    size_t sum = 0;
    for (size_t n : counts) sum += std::min(n, p);
    return sum;
  };
  if (kept(cap) >= target) return cap;
  size_t high = *std::max_element(counts.begin(), counts.end());
  while (cap + 1 < high) {  // kept(cap) < target <= kept(high).
    const size_t middle = cap + (high - cap) / 2;
    (kept(middle) >= target ? high : cap) = middle;
  }
  return high;
}

// ML-NDT Section 4.3, grid-based sampling, with the cap of GbsCap.
void SampleGbs(const SamplingOptions& options,
               const PointCloud& input,
               const VoxelGroups& cells,
               PointCloud* sampled,
               SamplingSummary* summary) {
  const size_t min_per_cell =
      static_cast<size_t>(options.gbs_min_points_per_cell);
  const size_t per_cell = GbsCap(options, cells, min_per_cell);
  summary->points_per_cell = per_cell;
  std::mt19937_64 rng(options.seed);
  std::vector<size_t> scratch;
  sampled->Reserve(std::min(input.size(), cells.num_voxels() * per_cell));
  for (size_t c = 0; c < cells.num_voxels(); ++c) {
    const size_t count = cells.num_points(c);
    const size_t* begin = cells.point_indices.data() + cells.offsets[c];
    if (count < min_per_cell) {
      ++summary->dropped_sparse_cells;
    } else if (count <= per_cell) {
      for (size_t i = 0; i < count; ++i) sampled->Add(input[begin[i]]);
    } else {
      scratch.assign(begin, begin + count);
      ChooseSubset(per_cell, &rng, &scratch);
      for (size_t i : scratch) sampled->Add(input[i]);
    }
  }
}

// Mean of each group, computed relative to the group's first point so that
// far-from-origin coordinates keep their precision.
void AppendCentroids(const PointCloud& input,
                     const VoxelGroups& voxels,
                     PointCloud* output) {
  output->Reserve(output->size() + voxels.num_voxels());
  for (size_t v = 0; v < voxels.num_voxels(); ++v) {
    const size_t count = voxels.num_points(v);
    const size_t* begin = voxels.point_indices.data() + voxels.offsets[v];
    const Eigen::Vector3d& origin = input[begin[0]];
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (size_t i = 1; i < count; ++i) sum += input[begin[i]] - origin;
    output->Add(origin + sum / static_cast<double>(count));
  }
}

}  // namespace

const EnumTable& SamplingMethodTable() {
  static const EnumTable table({
      {static_cast<int>(SamplingMethod::ALL), "ALL"},
      {static_cast<int>(SamplingMethod::RANDOM), "RANDOM"},
      {static_cast<int>(SamplingMethod::GBS), "GBS"},
      {static_cast<int>(SamplingMethod::VOXEL_CENTROID), "VOXEL_CENTROID"},
  });
  return table;
}

const char* SamplingMethodToString(SamplingMethod method) {
  return EnumToString(SamplingMethodTable(), method);
}

bool StringToSamplingMethod(std::string value, SamplingMethod* method) {
  return StringToEnum(SamplingMethodTable(), std::move(value), method);
}

const OptionTable& SamplingOptionsTable() {
  using S = SamplingOptions;
  static const OptionTable table =
      OptionTableBuilder<S>("SamplingOptions")
          .Enum("method",
                &S::method,
                SamplingMethodTable(),
                "Which input points become residuals (Section 4.3).")
          .Double("random_fraction",
                  &S::random_fraction,
                  "",
                  LeftOpen(0.0, 1.0),
                  "RANDOM: fraction of the input kept (used when random_count "
                  "== 0).")
          .Uint64("random_count",
                  &S::random_count,
                  "RANDOM: exact number of points kept when > 0.")
          .Double("gbs_cell_size_m",
                  &S::gbs_cell_size_m,
                  "m",
                  LeftOpen(0.0, kMaxSamplingCellM),
                  "GBS: cell edge.")
          .Int("gbs_points_per_cell",
               &S::gbs_points_per_cell,
               OptionRange(),
               "GBS: a cell with more points gives this many, at random (>= "
               "gbs_min_points_per_cell).")
          .Int("gbs_min_points_per_cell",
               &S::gbs_min_points_per_cell,
               AtLeast(1),
               "GBS: a cell with fewer points gives none.")
          .Int("gbs_min_samples",
               &S::gbs_min_samples,
               Closed(0, 100000000),
               "GBS: when the per-cell cap keeps fewer points, the cap is "
               "raised (the same for every cell) until this many are kept or "
               "every point of the cells that give any; 0 = off.")
          .Double("voxel_size_m",
                  &S::voxel_size_m,
                  "m",
                  LeftOpen(0.0, kMaxSamplingCellM),
                  "VOXEL_CENTROID: voxel edge.")
          .Uint64("seed", &S::seed, "Seed of every random choice.")
          .Validator(&S::IsValid)
          .Build();
  return table;
}

bool SamplingOptions::IsValid(std::string* error) const {
  if (!SamplingOptionsTable().Check(*this, error)) return false;
  MLNDT_OPTION_GE(gbs_points_per_cell, gbs_min_points_per_cell);
  return true;
}

bool SamplePoints(const SamplingOptions& options,
                  const PointCloud& input,
                  PointCloud* sampled,
                  SamplingSummary* summary,
                  std::string* error) {
  CHECK(sampled != nullptr);
  const auto start = std::chrono::steady_clock::now();
  *sampled = PointCloud();
  SamplingSummary local_summary;
  local_summary.input_points = input.size();
  auto finish = [&](bool ok) {
    if (!ok) *sampled = PointCloud();
    local_summary.sampled_points = sampled->size();
    local_summary.time_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
            .count();
    if (summary != nullptr) *summary = local_summary;
    return ok;
  };

  if (!options.IsValid(error)) return finish(false);
  if (input.empty()) {
    SetError("empty input", error);
    return finish(false);
  }
  for (size_t i = 0; i < input.size(); ++i) {
    if (!input[i].allFinite()) {
      SetError("non-finite point at index " + std::to_string(i), error);
      return finish(false);
    }
  }

  switch (options.method) {
    case SamplingMethod::ALL:
      *sampled = input;
      break;
    case SamplingMethod::RANDOM:
      SampleRandom(options, input, sampled);
      break;
    case SamplingMethod::GBS:
    case SamplingMethod::VOXEL_CENTROID: {
      const bool gbs = options.method == SamplingMethod::GBS;
      const double size = gbs ? options.gbs_cell_size_m : options.voxel_size_m;
      VoxelGroups groups;
      GroupPointsByVoxel(input.points(), size, &groups);
      if (groups.num_skipped > 0) {
        std::ostringstream message;
        message << "point at index " << groups.first_skipped_index
                << " is too far from the origin for "
                << (gbs ? "gbs_cell_size_m" : "voxel_size_m") << " = " << size;
        SetError(message.str(), error);
        return finish(false);
      }
      local_summary.occupied_cells = groups.num_voxels();
      if (gbs) {
        SampleGbs(options, input, groups, sampled, &local_summary);
      } else {
        AppendCentroids(input, groups, sampled);
      }
      break;
    }
  }
  return finish(true);
}

PointCloud VoxelDownsample(const PointCloud& input, double voxel_size_m) {
  CHECK(IsPositiveFinite(voxel_size_m)) << "voxel_size_m = " << voxel_size_m;
  VoxelGroups groups;
  GroupPointsByVoxel(input.points(), voxel_size_m, &groups);
  PointCloud output;
  AppendCentroids(input, groups, &output);
  return output;
}

}  // namespace mlndt
