#pragma once

// Which cell a transformed input point is scored against: the one place that
// decides what a point landing in no occupied cell contributes.
//
//  - ZERO_RESIDUAL: the point's own cell only (the paper's rule, Table 1); a
//    point in an empty cell contributes a zero residual and no gradient.
//  - NEAREST_CELL: the point's own cell if occupied, otherwise the occupied
//    cell among the 26 neighbours with the smallest Mahalanobis distance
//    e^T C^-1 e. Points just past a cell border keep pulling towards the
//    surface; points with no occupied neighbour still contribute zero.

#include <Eigen/Core>
#include <string>

#include "mlndt/grid/ndt_layer.h"

namespace mlndt {

class EnumTable;

enum class UnmatchedPolicy {
  ZERO_RESIDUAL,
  NEAREST_CELL,
};

// The names of UnmatchedPolicy's values (enum_table.h).
const EnumTable& UnmatchedPolicyTable();
const char* UnmatchedPolicyToString(UnmatchedPolicy policy);
bool StringToUnmatchedPolicy(std::string value, UnmatchedPolicy* policy);

// The cell `point` (a transformed input point, reference frame) is scored
// against, or nullptr when it contributes nothing.
const NdtCell* MatchCell(const NdtLayer& layer,
                         const Eigen::Vector3d& point,
                         UnmatchedPolicy policy);

}  // namespace mlndt
