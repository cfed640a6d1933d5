#include "mlndt/grid/cell_index.h"

#include <gtest/gtest.h>

namespace mlndt {
namespace {

TEST(CellIndex, DenseFindOrInsert) {
  CellIndex index(1000);
  EXPECT_EQ(index.Find(7), -1);
  EXPECT_EQ(index.FindOrInsert(7, 0), 0);
  EXPECT_EQ(index.FindOrInsert(7, 1), 0);  // Already there.
  EXPECT_EQ(index.FindOrInsert(999, 1), 1);
  EXPECT_EQ(index.Find(7), 0);
  EXPECT_EQ(index.Find(999), 1);
  EXPECT_EQ(index.Find(8), -1);
}

TEST(CellIndex, SparseFindOrInsert) {
  CellIndex index(CellIndex::kMaxDenseCells + 1);
  const int64_t far_key = CellIndex::kMaxDenseCells;
  EXPECT_EQ(index.Find(far_key), -1);
  EXPECT_EQ(index.FindOrInsert(far_key, 0), 0);
  EXPECT_EQ(index.FindOrInsert(far_key, 1), 0);
  EXPECT_EQ(index.FindOrInsert(3, 1), 1);
  EXPECT_EQ(index.Find(far_key), 0);
  EXPECT_EQ(index.Find(3), 1);
}

TEST(CellIndex, MemoryBytes) {
  EXPECT_EQ(CellIndex().MemoryBytes() % sizeof(void*), 0u);
  // The dense table: 4 bytes a grid cell, whatever it holds.
  CellIndex dense(1000);
  EXPECT_EQ(dense.MemoryBytes(),
            1000 * sizeof(int32_t) + CellIndex().MemoryBytes());
  dense.FindOrInsert(5, 0);
  EXPECT_EQ(dense.MemoryBytes(),
            1000 * sizeof(int32_t) + CellIndex().MemoryBytes());
  // The hash table grows with its entries: at least a node each.
  CellIndex sparse(CellIndex::kMaxDenseCells + 1);
  const size_t empty = sparse.MemoryBytes();
  for (int32_t i = 0; i < 1000; ++i) sparse.FindOrInsert(int64_t{i} * 1000, i);
  EXPECT_GE(sparse.MemoryBytes(),
            empty + 1000 * (sizeof(int64_t) + sizeof(int32_t)));
}

}  // namespace
}  // namespace mlndt
