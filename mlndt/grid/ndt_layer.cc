#include "mlndt/grid/ndt_layer.h"

#include <glog/logging.h>

namespace mlndt {

NdtLayer::NdtLayer(const Eigen::Vector3d& origin,
                   double cell_size,
                   const Eigen::Vector3i& dims,
                   std::vector<NdtCell> cells,
                   std::vector<int64_t> keys)
    : origin_(origin),
      cell_size_(cell_size),
      inverse_cell_size_(1.0 / cell_size),
      dims_(dims),
      cells_(std::move(cells)),
      keys_(std::move(keys)),
      index_(num_grid_cells()) {
  CHECK_EQ(cells_.size(), keys_.size());
  for (size_t i = 0; i < keys_.size(); ++i) {
    CHECK(keys_[i] >= 0 && keys_[i] < num_grid_cells())
        << "cell key out of range";
    CHECK_EQ(index_.FindOrInsert(keys_[i], static_cast<int32_t>(i)),
             static_cast<int32_t>(i))
        << "duplicate cell key " << keys_[i];
  }
}

size_t NdtLayer::MemoryBytes() const {
  return sizeof(NdtLayer) + cells_.capacity() * sizeof(NdtCell) +
         keys_.capacity() * sizeof(int64_t) + index_.MemoryBytes();
}

}  // namespace mlndt
