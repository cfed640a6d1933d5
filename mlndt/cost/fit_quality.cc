#include "mlndt/cost/fit_quality.h"

#include <algorithm>
#include <cmath>

#include "mlndt/cost/cell_match.h"
#include "mlndt/cost/transform_derivatives.h"

namespace mlndt {

FitQuality EvaluateFitQuality(const NdtLayer& layer,
                              const std::vector<Eigen::Vector3d>& input_points,
                              const Vector6d& reference_from_input_xi,
                              const ObjectiveOptions& objective,
                              double gate) {
  FitQuality quality;
  quality.points = input_points.size();
  if (input_points.empty()) return quality;
  const TransformDerivatives transform(reference_from_input_xi);
  size_t own = 0, inliers = 0;
  double score = 0.0;
  std::vector<double> distances;
  distances.reserve(input_points.size());
  for (const Eigen::Vector3d& p : input_points) {
    const Eigen::Vector3d x = transform.Transform(p);
    own += layer.Lookup(x) != nullptr;
    const NdtCell* cell = MatchCell(layer, x, objective.unmatched_policy);
    if (cell == nullptr) continue;
    const Eigen::Vector3d e = x - cell->mean;
    const double s = e.dot(cell->information * e);
    double rho = 0.0, rho_prime = 0.0;
    EvaluateLoss(LossType::CAUCHY, gate, s, &rho, &rho_prime);
    score += rho;
    inliers += s < gate * gate;
    distances.push_back(std::sqrt(s));
  }
  const double n = static_cast<double>(input_points.size());
  quality.own_cell_fraction = static_cast<double>(own) / n;
  quality.inlier_fraction = static_cast<double>(inliers) / n;
  if (!distances.empty()) {
    quality.mean_score = score / static_cast<double>(distances.size());
    const auto middle = distances.begin() + distances.size() / 2;
    std::nth_element(distances.begin(), middle, distances.end());
    quality.median_distance = *middle;
  }
  return quality;
}

}  // namespace mlndt
