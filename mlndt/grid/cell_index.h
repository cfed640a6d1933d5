#pragma once

// Maps a cell's linear key (ix + dx * (iy + dy * iz)) to a slot in a cell
// array in O(1): a dense table when the grid is small enough, a hash table
// otherwise (fine cells over a large extent).
//
// The hash table is a flat open-addressing table with linear probing: two
// parallel arrays of a power-of-two capacity, the keys (int64, -1 = empty)
// and the slots (int32), grown by doubling when more than 3/4 full. It holds
// 12 bytes a bucket, i.e. 16-32 bytes an entry (load 3/8 to 3/4), where a
// std::unordered_map<int64, int32> held a bucket pointer plus a separately
// allocated 24-byte node (32 bytes from malloc) per entry, and spent most of
// a large map's build time in malloc and pointer chasing (docs/maps.md has
// the measurements). The bucket of a key is the top bits of
// key * 2^64 / phi (Fibonacci hashing), which spreads the arithmetic
// progressions of grid keys (rows, planes) evenly.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace mlndt {

class CellIndex {
 public:
  // Grids with at most this many cells use the dense table (4 bytes a cell).
  static constexpr int64_t kMaxDenseCells = int64_t{1} << 24;

  CellIndex() = default;
  // An index for keys in [0, num_grid_cells).
  explicit CellIndex(int64_t num_grid_cells);

  // The slot stored for `key` (in [0, num_grid_cells)), or -1.
  int32_t Find(int64_t key) const {
    if (!dense_.empty()) return dense_[static_cast<size_t>(key)];
    if (keys_.empty()) return -1;
    for (size_t b = Bucket(key);; b = (b + 1) & mask_) {
      const int64_t k = keys_[b];
      if (k == key) return slots_[b];
      if (k == kEmptyKey) return -1;
    }
  }

  // The slot of `key`; if it has none, stores `new_slot` (>= 0) and returns
  // it.
  int32_t FindOrInsert(int64_t key, int32_t new_slot) {
    if (!dense_.empty()) {
      int32_t& slot = dense_[static_cast<size_t>(key)];
      if (slot < 0) slot = new_slot;
      return slot;
    }
    return HashedFindOrInsert(key, new_slot);
  }

  bool is_dense() const { return !dense_.empty(); }
  // The dense table (slot or -1 per key), or nullptr for a hashed index:
  // for scans over neighbouring keys without a branch per key on the kind
  // of index (cell_match.h).
  const int32_t* dense_slots() const {
    return dense_.empty() ? nullptr : dense_.data();
  }
  // Keys stored in the hash table (0 for a dense index).
  size_t num_hashed() const { return num_hashed_; }

  // Heap bytes of the table: the dense vector's capacity (4 bytes a grid
  // cell), or the hash table's 12 bytes a bucket.
  size_t MemoryBytes() const;

  // The MemoryBytes() of an index over `num_grid_cells` cells after
  // `num_keys` distinct keys were inserted one by one: for estimating a
  // map's memory before building it (map_memory.h).
  static size_t EstimateBytes(int64_t num_grid_cells, size_t num_keys);

 private:
  static constexpr int64_t kEmptyKey = -1;
  static constexpr size_t kMinBuckets = 16;

  size_t Bucket(int64_t key) const {
    return static_cast<size_t>(
        (static_cast<uint64_t>(key) * 0x9E3779B97F4A7C15ull) >> shift_);
  }
  int32_t HashedFindOrInsert(int64_t key, int32_t new_slot);
  void Rehash(size_t num_buckets);

  std::vector<int32_t> dense_;
  std::vector<int64_t> keys_;   // Hash buckets: key or kEmptyKey.
  std::vector<int32_t> slots_;  // Hash buckets: the key's slot.
  size_t mask_ = 0;             // Buckets - 1.
  int shift_ = 64;              // 64 - log2(buckets).
  size_t num_hashed_ = 0;
};

}  // namespace mlndt
