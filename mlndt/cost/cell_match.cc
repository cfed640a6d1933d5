#include "mlndt/cost/cell_match.h"

#include <limits>

#include "mlndt/common/enum_table.h"

namespace mlndt {

const EnumTable& UnmatchedPolicyTable() {
  static const EnumTable table({
      {static_cast<int>(UnmatchedPolicy::ZERO_RESIDUAL), "ZERO_RESIDUAL"},
      {static_cast<int>(UnmatchedPolicy::NEAREST_CELL), "NEAREST_CELL"},
  });
  return table;
}

const char* UnmatchedPolicyToString(UnmatchedPolicy policy) {
  return EnumToString(UnmatchedPolicyTable(), policy);
}

bool StringToUnmatchedPolicy(std::string value, UnmatchedPolicy* policy) {
  return StringToEnum(UnmatchedPolicyTable(), std::move(value), policy);
}

namespace {

// The nearest-cell search's running best: the smallest Mahalanobis distance
// e^T C^-1 e (Eq. 10's score term) so far; the first of equals wins.
struct NearestCell {
  const NdtCell* cell = nullptr;
  double distance = std::numeric_limits<double>::infinity();

  void Consider(const Eigen::Vector3d& point, const NdtCell* candidate) {
    if (candidate == nullptr) return;
    const Eigen::Vector3d e = point - candidate->mean;
    const double d = e.dot(candidate->information * e);
    if (d < distance) {
      distance = d;
      cell = candidate;
    }
  }
};

}  // namespace

const NdtCell* MatchCell(const NdtLayer& layer,
                         const Eigen::Vector3d& point,
                         UnmatchedPolicy policy) {
  const Eigen::Vector3i ijk = layer.CellCoordinates(point);
  const NdtCell* own = layer.CellAt(ijk);
  if (own != nullptr || policy == UnmatchedPolicy::ZERO_RESIDUAL) return own;
  // The 27 cells around ijk in (dz, dy, dx) order, ijk's own (empty) included.
  NearestCell nearest;
  if (layer.NeighboursInside(ijk)) {
    // Inside the grid the neighbours' keys are the centre's plus offsets:
    // no bounds check and no key arithmetic per neighbour.
    const int64_t step_y = layer.dims().x();
    const int64_t step_z = step_y * layer.dims().y();
    const int64_t centre = layer.LinearKey(ijk);
    if (const int32_t* slots = layer.dense_slots()) {
      // A dense index: three loads a row, no per-key test of the index's
      // kind (the search's cost is these 27 probes; few are occupied).
      const NdtCell* cells = layer.cells().data();
      for (int64_t dz = -step_z; dz <= step_z; dz += step_z) {
        for (int64_t dy = -step_y; dy <= step_y; dy += step_y) {
          const int32_t* row = slots + (centre + dz + dy - 1);
          for (int dx = 0; dx < 3; ++dx) {
            if (row[dx] >= 0) nearest.Consider(point, cells + row[dx]);
          }
        }
      }
      return nearest.cell;
    }
    for (int64_t dz = -step_z; dz <= step_z; dz += step_z) {
      for (int64_t dy = -step_y; dy <= step_y; dy += step_y) {
        const int64_t row = centre + dz + dy;
        for (int64_t dx = -1; dx <= 1; ++dx) {
          nearest.Consider(point, layer.CellAtKey(row + dx));
        }
      }
    }
    return nearest.cell;
  }
  for (int dz = -1; dz <= 1; ++dz) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        nearest.Consider(point,
                         layer.CellAt(ijk + Eigen::Vector3i(dx, dy, dz)));
      }
    }
  }
  return nearest.cell;
}

}  // namespace mlndt
