#include "mlndt/cost/point_matches.h"

namespace mlndt {

PointMatch MatchPoint(const NdtLayer& layer,
                      const Eigen::Vector3d& x,
                      UnmatchedPolicy policy) {
  PointMatch m;
  m.x = x;
  m.cell = layer.Lookup(x);
  m.own_cell = m.cell != nullptr;
  // An occupied own cell is also the one MatchCell picks under either
  // policy; only the others need its search.
  if (m.cell == nullptr) m.cell = MatchCell(layer, x, policy);
  if (m.cell == nullptr) return m;
  // The fit is judged on the distribution the cell holds (its whole
  // covariance), also where the objective scores its normal only: along the
  // normal alone, a wrong pose that lays its points on some plane fits as
  // well as the right one.
  const Eigen::Vector3d e = x - m.cell->mean;
  m.score = m.cell->normal_only ? e.dot(m.cell->covariance.ldlt().solve(e))
                                : e.dot(m.cell->information * e);
  return m;
}

std::vector<PointMatch> MatchPoints(
    const NdtLayer& layer,
    const std::vector<Eigen::Vector3d>& input_points,
    const Matrix3d& rotation,
    const Eigen::Vector3d& translation,
    UnmatchedPolicy policy) {
  std::vector<PointMatch> matches;
  matches.reserve(input_points.size());
  for (const Eigen::Vector3d& p : input_points) {
    matches.push_back(MatchPoint(layer, rotation * p + translation, policy));
  }
  return matches;
}

}  // namespace mlndt
