#include "mlndt/cost/point_matches.h"

namespace mlndt {

std::vector<PointMatch> MatchPoints(
    const NdtLayer& layer,
    const std::vector<Eigen::Vector3d>& input_points,
    const Matrix3d& rotation,
    const Eigen::Vector3d& translation,
    UnmatchedPolicy policy) {
  std::vector<PointMatch> matches(input_points.size());
  for (size_t k = 0; k < input_points.size(); ++k) {
    PointMatch& m = matches[k];
    m.x = rotation * input_points[k] + translation;
    m.cell = layer.Lookup(m.x);
    m.own_cell = m.cell != nullptr;
    // An occupied own cell is also the one MatchCell picks under either
    // policy; only the others need its search.
    if (m.cell == nullptr) m.cell = MatchCell(layer, m.x, policy);
    if (m.cell == nullptr) continue;
    const Eigen::Vector3d e = m.x - m.cell->mean;
    m.score = e.dot(m.cell->information * e);
  }
  return matches;
}

}  // namespace mlndt
