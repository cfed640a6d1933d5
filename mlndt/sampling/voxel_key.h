#pragma once

// Integer voxel keys and a linear-time "group points by voxel" helper,
// shared by the samplers (GBS, voxel centroids) and anything else that bins
// points into an axis-aligned grid of cubes.
//
// A point p falls in the voxel whose integer coordinates are
// floor(p / voxel_size) per axis. The three coordinates are kept as separate
// int64 values (no packing into one 64-bit word), so keys stay exact for
// coordinates far from the origin (e.g. UTM, 4e6 m) and for any extent.
// Coordinates whose voxel index would leave [-kMaxVoxelIndex, kMaxVoxelIndex]
// are rejected instead of overflowing.

#include <glog/logging.h>

#include <Eigen/Core>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "mlndt/common/fast_floor.h"

namespace mlndt {

// Largest |voxel index| a key may hold (2^62): floor() of anything larger is
// not representable exactly and could overflow int64 arithmetic on neighbours.
constexpr double kMaxVoxelIndex = 4611686018427387904.0;

// Integer coordinates of one voxel.
struct VoxelKey {
  int64_t x = 0;
  int64_t y = 0;
  int64_t z = 0;

  bool operator==(const VoxelKey& other) const {
    return x == other.x && y == other.y && z == other.z;
  }
  bool operator!=(const VoxelKey& other) const { return !(*this == other); }
  // Lexicographic (x, y, z) order, for sort-based grouping.
  bool operator<(const VoxelKey& other) const {
    if (x != other.x) return x < other.x;
    if (y != other.y) return y < other.y;
    return z < other.z;
  }
};

// Well-mixed 64-bit hash of a key (usable with std::unordered_map). The
// result does not influence any output order in this library.
struct VoxelKeyHash {
  size_t operator()(const VoxelKey& key) const {
    uint64_t h = static_cast<uint64_t>(key.x) * 0x9E3779B97F4A7C15ull;
    h ^= static_cast<uint64_t>(key.y) * 0xC2B2AE3D27D4EB4Full;
    h ^= static_cast<uint64_t>(key.z) * 0x165667B19E3779F9ull;
    // splitmix64 finaliser.
    h ^= h >> 30;
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 27;
    h *= 0x94D049BB133111EBull;
    h ^= h >> 31;
    return static_cast<size_t>(h);
  }
};

// Computes the key floor(point / voxel_size_m) of `point` for voxels of edge
// `voxel_size_m` [m] (> 0). Returns false (and leaves *key untouched) when a
// coordinate is not finite or its voxel index exceeds kMaxVoxelIndex in
// magnitude.
inline bool ComputeVoxelKey(const Eigen::Vector3d& point,
                            double voxel_size_m,
                            VoxelKey* key) {
  const double fx = point.x() / voxel_size_m;
  const double fy = point.y() / voxel_size_m;
  const double fz = point.z() / voxel_size_m;
  // The negated comparisons also reject NaN.
  if (!(std::abs(fx) <= kMaxVoxelIndex) || !(std::abs(fy) <= kMaxVoxelIndex) ||
      !(std::abs(fz) <= kMaxVoxelIndex)) {
    return false;
  }
  key->x = FloorToInt64(fx);
  key->y = FloorToInt64(fy);
  key->z = FloorToInt64(fz);
  return true;
}

// Minimum corner of the voxel `key` for voxels of edge `voxel_size` [m].
inline Eigen::Vector3d VoxelMinCorner(const VoxelKey& key, double voxel_size) {
  return Eigen::Vector3d(static_cast<double>(key.x),
                         static_cast<double>(key.y),
                         static_cast<double>(key.z)) *
         voxel_size;
}

// Centre of the voxel `key` for voxels of edge `voxel_size` [m].
inline Eigen::Vector3d VoxelCenter(const VoxelKey& key, double voxel_size) {
  return VoxelMinCorner(key, voxel_size) +
         Eigen::Vector3d::Constant(0.5 * voxel_size);
}

// Points grouped by voxel, in CSR form. Voxels are listed in order of first
// appearance in the input; inside a voxel the point indices are in input
// order. The order therefore depends only on the input, never on hashing.
struct VoxelGroups {
  std::vector<VoxelKey> keys;  // One per occupied voxel.
  // Voxel v owns point_indices[offsets[v], offsets[v + 1]); size keys+1.
  std::vector<size_t> offsets;
  std::vector<size_t> point_indices;  // Indices into the input points.
  size_t num_skipped = 0;  // Points with no key (non-finite / out of range).
  // Index of the first skipped point; meaningful when num_skipped > 0.
  size_t first_skipped_index = 0;

  size_t num_voxels() const { return keys.size(); }
  size_t num_points(size_t v) const { return offsets[v + 1] - offsets[v]; }
};

// Groups `points` by voxels of edge `voxel_size_m` [m] (finite, > 0) in
// O(n) expected time: an open-addressing hash table assigns a voxel id to
// each point, then a counting sort lays the indices out per voxel. Points
// without a valid key are skipped and counted in groups->num_skipped.
inline void GroupPointsByVoxel(const std::vector<Eigen::Vector3d>& points,
                               double voxel_size_m,
                               VoxelGroups* groups) {
  CHECK(groups != nullptr);
  CHECK(std::isfinite(voxel_size_m) && voxel_size_m > 0.0)
      << "voxel_size_m = " << voxel_size_m;
  CHECK_LT(points.size(), size_t{std::numeric_limits<uint32_t>::max()});
  *groups = VoxelGroups();
  const size_t n = points.size();

  // Open addressing with linear probing; the capacity is a power of two that
  // doubles whenever the load factor would pass 1/2, so the table stays
  // small (cache-resident) when the voxels are much fewer than the points.
  constexpr uint32_t kEmpty = std::numeric_limits<uint32_t>::max();
  std::vector<uint32_t> table(1024, kEmpty);  // Slot -> voxel id.
  size_t mask = table.size() - 1;
  const VoxelKeyHash hash;
  auto grow = [&]() {
    table.assign(2 * table.size(), kEmpty);
    mask = table.size() - 1;
    for (uint32_t id = 0; id < groups->keys.size(); ++id) {
      size_t slot = hash(groups->keys[id]) & mask;
      while (table[slot] != kEmpty) slot = (slot + 1) & mask;
      table[slot] = id;
    }
  };

  constexpr uint32_t kNoVoxel = std::numeric_limits<uint32_t>::max();
  std::vector<uint32_t> voxel_of_point(n, kNoVoxel);
  std::vector<size_t> counts;
  // Consecutive scan points often share a voxel: remember the last one.
  VoxelKey last_key;
  uint32_t last_id = kNoVoxel;
  for (size_t i = 0; i < n; ++i) {
    VoxelKey key;
    if (!ComputeVoxelKey(points[i], voxel_size_m, &key)) {
      if (groups->num_skipped == 0) groups->first_skipped_index = i;
      ++groups->num_skipped;
      continue;
    }
    if (last_id == kNoVoxel || key != last_key) {
      size_t slot = hash(key) & mask;
      while (true) {
        const uint32_t id = table[slot];
        if (id == kEmpty) {
          last_id = static_cast<uint32_t>(groups->keys.size());
          table[slot] = last_id;
          groups->keys.push_back(key);
          counts.push_back(0);
          if (2 * groups->keys.size() > table.size()) grow();
          break;
        }
        if (groups->keys[id] == key) {
          last_id = id;
          break;
        }
        slot = (slot + 1) & mask;
      }
      last_key = key;
    }
    voxel_of_point[i] = last_id;
    ++counts[last_id];
  }

  // Counting sort: prefix sums, then a stable scatter in input order.
  const size_t num_voxels = groups->keys.size();
  groups->offsets.assign(num_voxels + 1, 0);
  for (size_t v = 0; v < num_voxels; ++v) {
    groups->offsets[v + 1] = groups->offsets[v] + counts[v];
  }
  groups->point_indices.resize(groups->offsets[num_voxels]);
  std::vector<size_t> cursor(groups->offsets.begin(),
                             groups->offsets.end() - 1);
  for (size_t i = 0; i < n; ++i) {
    const uint32_t v = voxel_of_point[i];
    if (v == kNoVoxel) continue;
    groups->point_indices[cursor[v]++] = i;
  }
}

}  // namespace mlndt
