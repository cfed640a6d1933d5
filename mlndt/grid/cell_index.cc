#include "mlndt/grid/cell_index.h"

namespace mlndt {

CellIndex::CellIndex(int64_t num_grid_cells) {
  if (num_grid_cells <= kMaxDenseCells) {
    dense_.assign(static_cast<size_t>(num_grid_cells), -1);
  }
}

int32_t CellIndex::FindOrInsert(int64_t key, int32_t new_slot) {
  if (!dense_.empty()) {
    int32_t& slot = dense_[static_cast<size_t>(key)];
    if (slot < 0) slot = new_slot;
    return slot;
  }
  return sparse_.emplace(key, new_slot).first->second;
}

}  // namespace mlndt
