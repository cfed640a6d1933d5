#include "mlndt/cost/cell_match.h"

#include <limits>

#include "mlndt/common/internal/enum_strings.h"

namespace mlndt {

const char* UnmatchedPolicyToString(UnmatchedPolicy policy) {
  switch (policy) {
    case UnmatchedPolicy::ZERO_RESIDUAL:
      return "ZERO_RESIDUAL";
    case UnmatchedPolicy::NEAREST_CELL:
      return "NEAREST_CELL";
  }
  return "UNKNOWN";
}

bool StringToUnmatchedPolicy(std::string value, UnmatchedPolicy* result) {
  UpperCase(&value);
  MLNDT_STRING_TO_ENUM(ZERO_RESIDUAL, UnmatchedPolicy);
  MLNDT_STRING_TO_ENUM(NEAREST_CELL, UnmatchedPolicy);
  return false;
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
