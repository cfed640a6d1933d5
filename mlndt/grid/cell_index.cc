#include "mlndt/grid/cell_index.h"

namespace mlndt {

CellIndex::CellIndex(int64_t num_grid_cells) {
  if (num_grid_cells <= kMaxDenseCells) {
    dense_.assign(static_cast<size_t>(num_grid_cells), -1);
  }
}

}  // namespace mlndt
