#include "mlndt/grid/cell_index.h"

namespace mlndt {

CellIndex::CellIndex(int64_t num_grid_cells) {
  if (num_grid_cells <= kMaxDenseCells) {
    dense_.assign(static_cast<size_t>(num_grid_cells), -1);
  }
}

size_t CellIndex::MemoryBytes() const {
  using Map = std::unordered_map<int64_t, int32_t>;
  // A libstdc++ node holds the next pointer and the (key, slot) pair; int64
  // keys do not cache their hash.
  const size_t node_bytes = sizeof(void*) + sizeof(Map::value_type);
  return dense_.capacity() * sizeof(int32_t) +
         sparse_.bucket_count() * sizeof(void*) + sparse_.size() * node_bytes;
}

}  // namespace mlndt
