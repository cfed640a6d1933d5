#include "mlndt/grid/cell_index.h"

#include <gtest/gtest.h>

#include <random>
#include <unordered_map>

namespace mlndt {
namespace {

constexpr int64_t kHashedGrid = CellIndex::kMaxDenseCells + 1;

TEST(CellIndex, DenseFindOrInsert) {
  CellIndex index(1000);
  EXPECT_TRUE(index.is_dense());
  EXPECT_EQ(index.Find(7), -1);
  EXPECT_EQ(index.FindOrInsert(7, 0), 0);
  EXPECT_EQ(index.FindOrInsert(7, 1), 0);  // Already there.
  EXPECT_EQ(index.FindOrInsert(999, 1), 1);
  EXPECT_EQ(index.Find(7), 0);
  EXPECT_EQ(index.Find(999), 1);
  EXPECT_EQ(index.Find(8), -1);
}

TEST(CellIndex, SparseFindOrInsert) {
  CellIndex index(kHashedGrid);
  EXPECT_FALSE(index.is_dense());
  const int64_t far_key = CellIndex::kMaxDenseCells;
  EXPECT_EQ(index.Find(far_key), -1);  // Before any table exists.
  EXPECT_EQ(index.FindOrInsert(far_key, 0), 0);
  EXPECT_EQ(index.FindOrInsert(far_key, 1), 0);
  EXPECT_EQ(index.FindOrInsert(3, 1), 1);
  EXPECT_EQ(index.Find(far_key), 0);
  EXPECT_EQ(index.Find(3), 1);
  EXPECT_EQ(index.Find(4), -1);
  EXPECT_EQ(index.FindOrInsert(0, 2), 2);  // Key 0 is a key, not "empty".
  EXPECT_EQ(index.Find(0), 2);
  EXPECT_EQ(index.num_hashed(), 3u);
}

// Against std::unordered_map over many growths, with the key patterns of a
// grid: random cells, whole rows, and strides of powers of two (the worst
// case for a hash that keeps low bits).
TEST(CellIndex, HashedMatchesUnorderedMapThroughGrowth) {
  const int64_t num_grid_cells = int64_t{4000} * 4000 * 40;
  CellIndex index(num_grid_cells);
  std::unordered_map<int64_t, int32_t> reference;
  std::mt19937_64 rng(7);
  std::vector<int64_t> keys;
  for (int i = 0; i < 30000; ++i) {
    keys.push_back(static_cast<int64_t>(rng() % num_grid_cells));
  }
  for (int64_t x = 0; x < 20000; ++x) keys.push_back(123456 + x);  // A row.
  for (int64_t k = 0; k < 20000; ++k) keys.push_back(k << 12);     // Stride.
  for (int i = 0; i < 10000; ++i) keys.push_back(keys[rng() % keys.size()]);
  for (const int64_t key : keys) {
    const int32_t new_slot = static_cast<int32_t>(reference.size());
    const int32_t expected = reference.emplace(key, new_slot).first->second;
    ASSERT_EQ(index.FindOrInsert(key, new_slot), expected) << key;
  }
  EXPECT_EQ(index.num_hashed(), reference.size());
  for (const auto& [key, slot] : reference) ASSERT_EQ(index.Find(key), slot);
  for (int i = 0; i < 20000; ++i) {
    const int64_t key = static_cast<int64_t>(rng() % num_grid_cells);
    const auto it = reference.find(key);
    ASSERT_EQ(index.Find(key), it == reference.end() ? -1 : it->second);
  }
}

TEST(CellIndex, MemoryBytes) {
  EXPECT_EQ(CellIndex().MemoryBytes(), 0u);
  // The dense table: 4 bytes a grid cell, whatever it holds.
  CellIndex dense(1000);
  EXPECT_EQ(dense.MemoryBytes(), 1000 * sizeof(int32_t));
  dense.FindOrInsert(5, 0);
  EXPECT_EQ(dense.MemoryBytes(), 1000 * sizeof(int32_t));
  // The hash table: 12 bytes a bucket, at most 3/4 of the buckets used and
  // (after the first growths) at least 3/8.
  CellIndex sparse(kHashedGrid);
  EXPECT_EQ(sparse.MemoryBytes(), 0u);
  for (int32_t i = 0; i < 100000; ++i) {
    sparse.FindOrInsert(int64_t{i} * 1000, i);
    const size_t buckets = sparse.MemoryBytes() / 12;
    ASSERT_EQ(sparse.MemoryBytes() % 12, 0u);
    ASSERT_LE(4 * size_t(i + 1), 3 * buckets);
    if (i >= 16) ASSERT_GE(8 * size_t(i + 1), 3 * buckets);
  }
  EXPECT_LE(sparse.MemoryBytes(), 100000u * 32);
}

// The estimate used before a map is built equals what the index holds.
TEST(CellIndex, EstimateBytesEqualsMemoryBytes) {
  EXPECT_EQ(CellIndex::EstimateBytes(1000, 0), CellIndex(1000).MemoryBytes());
  EXPECT_EQ(CellIndex::EstimateBytes(1000, 10), 4000u);
  EXPECT_EQ(CellIndex::EstimateBytes(kHashedGrid, 0), 0u);
  CellIndex sparse(kHashedGrid);
  for (int32_t i = 0; i < 5000; ++i) {
    sparse.FindOrInsert(int64_t{i} * 977, i);
    ASSERT_EQ(CellIndex::EstimateBytes(kHashedGrid, size_t(i + 1)),
              sparse.MemoryBytes())
        << i;
  }
}

}  // namespace
}  // namespace mlndt
