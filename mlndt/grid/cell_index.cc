#include "mlndt/grid/cell_index.h"

#include <glog/logging.h>

#include <algorithm>

namespace mlndt {
namespace {

// The bucket count after `num_keys` insertions: the smallest power of two
// >= kMinBuckets that keeps the table at most 3/4 full (0 for no keys).
size_t BucketsFor(size_t num_keys, size_t min_buckets) {
  if (num_keys == 0) return 0;
  size_t buckets = min_buckets;
  while (num_keys * 4 > buckets * 3) buckets *= 2;
  return buckets;
}

}  // namespace

CellIndex::CellIndex(int64_t num_grid_cells) {
  if (num_grid_cells <= kMaxDenseCells) {
    dense_.assign(static_cast<size_t>(num_grid_cells), -1);
  }
}

int32_t CellIndex::HashedFindOrInsert(int64_t key, int32_t new_slot) {
  DCHECK_GE(key, 0);
  DCHECK_GE(new_slot, 0);
  if ((num_hashed_ + 1) * 4 > keys_.size() * 3) {
    Rehash(std::max(kMinBuckets, 2 * keys_.size()));
  }
  for (size_t b = Bucket(key);; b = (b + 1) & mask_) {
    const int64_t k = keys_[b];
    if (k == key) return slots_[b];
    if (k == kEmptyKey) {
      keys_[b] = key;
      slots_[b] = new_slot;
      ++num_hashed_;
      return new_slot;
    }
  }
}

void CellIndex::Rehash(size_t num_buckets) {
  std::vector<int64_t> old_keys(num_buckets, kEmptyKey);
  std::vector<int32_t> old_slots(num_buckets, -1);
  old_keys.swap(keys_);
  old_slots.swap(slots_);
  mask_ = num_buckets - 1;
  shift_ = 64;
  for (size_t b = num_buckets; b > 1; b >>= 1) --shift_;
  for (size_t i = 0; i < old_keys.size(); ++i) {
    if (old_keys[i] == kEmptyKey) continue;
    size_t b = Bucket(old_keys[i]);
    while (keys_[b] != kEmptyKey) b = (b + 1) & mask_;
    keys_[b] = old_keys[i];
    slots_[b] = old_slots[i];
  }
}

size_t CellIndex::MemoryBytes() const {
  return dense_.capacity() * sizeof(int32_t) +
         keys_.capacity() * sizeof(int64_t) +
         slots_.capacity() * sizeof(int32_t);
}

size_t CellIndex::EstimateBytes(int64_t num_grid_cells, size_t num_keys) {
  if (num_grid_cells > 0 && num_grid_cells <= kMaxDenseCells) {
    return static_cast<size_t>(num_grid_cells) * sizeof(int32_t);
  }
  return BucketsFor(num_keys, kMinBuckets) *
         (sizeof(int64_t) + sizeof(int32_t));
}

}  // namespace mlndt
