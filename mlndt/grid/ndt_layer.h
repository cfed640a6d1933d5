#pragma once

// One layer of the layered NDT map: a regular grid of cubic cells of edge
// `cell_size` [m] over the reference scan's bounding box, keeping the cells
// that hold enough points (ML-NDT Section 4, Table 1, "generative process").

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <vector>

#include "mlndt/common/fast_floor.h"
#include "mlndt/grid/cell_index.h"
#include "mlndt/grid/ndt_cell.h"

namespace mlndt {

class NdtLayer {
 public:
  NdtLayer() = default;
  // `keys[i]` is the linear key of `cells[i]`; keys are unique and in range.
  NdtLayer(const Eigen::Vector3d& origin,
           double cell_size,
           const Eigen::Vector3i& dims,
           std::vector<NdtCell> cells,
           std::vector<int64_t> keys);

  const Eigen::Vector3d& origin() const { return origin_; }  // Min corner [m].
  double cell_size() const { return cell_size_; }            // Cell edge [m].
  const Eigen::Vector3i& dims() const { return dims_; }      // Cells per axis.
  int64_t num_grid_cells() const {
    return int64_t{dims_.x()} * dims_.y() * dims_.z();
  }
  const std::vector<NdtCell>& cells() const { return cells_; }  // Occupied.
  const std::vector<int64_t>& keys() const { return keys_; }

  // Bytes this layer holds: sizeof(NdtLayer), the cell and key vectors'
  // capacity, and the cell index (a dense table of 4 bytes per grid cell, or
  // a hash table; see CellIndex::MemoryBytes).
  size_t MemoryBytes() const;

  // Integer cell coordinates of `point` (may lie outside the grid). Points
  // beyond the grid's border cells are put two cells out, so that not even
  // their neighbours are inside, and so are non-finite points.
  Eigen::Vector3i CellCoordinates(const Eigen::Vector3d& point) const {
    Eigen::Vector3i ijk;
    for (int a = 0; a < 3; ++a) {
      const double s = (point(a) - origin_(a)) * inverse_cell_size_;
      if (!(s >= -1.0)) {  // Also NaN.
        ijk(a) = -2;
      } else if (!(s < dims_(a) + 1.0)) {
        ijk(a) = dims_(a) + 1;
      } else {
        ijk(a) = static_cast<int>(FloorToInt64(s));
      }
    }
    return ijk;
  }

  // The occupied cell at integer coordinates `ijk`, or nullptr.
  const NdtCell* CellAt(const Eigen::Vector3i& ijk) const {
    if ((ijk.array() < 0).any() || (ijk.array() >= dims_.array()).any()) {
      return nullptr;
    }
    const int32_t slot = index_.Find(LinearKey(ijk));
    return slot < 0 ? nullptr : &cells_[static_cast<size_t>(slot)];
  }

  // The occupied cell of linear key `key` (LinearKey of coordinates inside
  // the grid; not checked), or nullptr.
  const NdtCell* CellAtKey(int64_t key) const {
    const int32_t slot = index_.Find(key);
    return slot < 0 ? nullptr : &cells_[static_cast<size_t>(slot)];
  }

  // The cell index's dense table (CellIndex::dense_slots: the slot in
  // cells() of every linear key, or -1), or nullptr when it is hashed.
  const int32_t* dense_slots() const { return index_.dense_slots(); }

  // True when `ijk` and its 26 neighbours all lie inside the grid, so that
  // the neighbours' keys are LinearKey(ijk) plus fixed offsets.
  bool NeighboursInside(const Eigen::Vector3i& ijk) const {
    return (ijk.array() >= 1).all() && (ijk.array() < dims_.array() - 1).all();
  }

  // O(1) lookup of the occupied cell containing `point`, or nullptr.
  const NdtCell* Lookup(const Eigen::Vector3d& point) const {
    return CellAt(CellCoordinates(point));
  }

  int64_t LinearKey(const Eigen::Vector3i& ijk) const {
    return ijk.x() +
           int64_t{dims_.x()} * (ijk.y() + int64_t{dims_.y()} * ijk.z());
  }

 private:
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();
  double cell_size_ = 0.0;
  double inverse_cell_size_ = 0.0;
  Eigen::Vector3i dims_ = Eigen::Vector3i::Zero();
  std::vector<NdtCell> cells_;
  std::vector<int64_t> keys_;
  CellIndex index_;
};

}  // namespace mlndt
