#pragma once

// Maps a cell's linear key (ix + dx * (iy + dy * iz)) to a slot in a cell
// array in O(1): a dense table when the grid is small enough, a hash table
// otherwise (fine cells over a large extent).

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace mlndt {

class CellIndex {
 public:
  // Grids with at most this many cells use the dense table (4 bytes a cell).
  static constexpr int64_t kMaxDenseCells = int64_t{1} << 24;

  CellIndex() = default;
  explicit CellIndex(int64_t num_grid_cells);

  // The slot stored for `key`, or -1.
  int32_t Find(int64_t key) const {
    if (!dense_.empty()) return dense_[static_cast<size_t>(key)];
    const auto it = sparse_.find(key);
    return it == sparse_.end() ? -1 : it->second;
  }

  // The slot of `key`; if it has none, stores `new_slot` and returns it.
  int32_t FindOrInsert(int64_t key, int32_t new_slot) {
    if (!dense_.empty()) {
      int32_t& slot = dense_[static_cast<size_t>(key)];
      if (slot < 0) slot = new_slot;
      return slot;
    }
    return sparse_.emplace(key, new_slot).first->second;
  }

  // Heap bytes of the table: the dense vector's capacity, or the hash
  // table's buckets plus one node (next pointer, key, slot) per entry,
  // without the allocator's per-node overhead.
  size_t MemoryBytes() const;

 private:
  std::vector<int32_t> dense_;
  std::unordered_map<int64_t, int32_t> sparse_;
};

}  // namespace mlndt
