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

const NdtCell* MatchCell(const NdtLayer& layer,
                         const Eigen::Vector3d& point,
                         UnmatchedPolicy policy) {
  const Eigen::Vector3i ijk = layer.CellCoordinates(point);
  const NdtCell* own = layer.CellAt(ijk);
  if (own != nullptr || policy == UnmatchedPolicy::ZERO_RESIDUAL) return own;
  const NdtCell* best = nullptr;
  double best_distance = std::numeric_limits<double>::infinity();
  for (int dz = -1; dz <= 1; ++dz) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const NdtCell* cell = layer.CellAt(ijk + Eigen::Vector3i(dx, dy, dz));
        if (cell == nullptr) continue;
        const Eigen::Vector3d e = point - cell->mean;
        const double distance = e.dot(cell->information * e);
        if (distance < best_distance) {
          best_distance = distance;
          best = cell;
        }
      }
    }
  }
  return best;
}

}  // namespace mlndt
