#include "mlndt/cost/fit_quality.h"

#include <algorithm>
#include <cmath>

#include "mlndt/cost/transform_derivatives.h"

namespace mlndt {

FitQuality EvaluateFitQuality(const NdtLayer& layer,
                              const std::vector<Eigen::Vector3d>& input_points,
                              const Vector6d& reference_from_input_xi,
                              const ObjectiveOptions& objective,
                              double gate) {
  const TransformDerivatives transform(reference_from_input_xi);
  return FitQualityOf(MatchPoints(layer,
                                  input_points,
                                  transform.rotation(),
                                  transform.translation(),
                                  objective.unmatched_policy),
                      gate);
}

FitQuality FitQualityOf(const std::vector<PointMatch>& matches, double gate) {
  FitQuality quality;
  quality.points = matches.size();
  if (matches.empty()) return quality;
  size_t own = 0, inliers = 0;
  double score = 0.0;
  std::vector<double> distances;
  distances.reserve(matches.size());
  for (const PointMatch& m : matches) {
    own += m.own_cell;
    if (m.cell == nullptr) continue;
    double rho = 0.0, rho_prime = 0.0;
    EvaluateLoss(LossType::CAUCHY, gate, m.score, &rho, &rho_prime);
    score += rho;
    inliers += m.IsInlier(gate);
    distances.push_back(std::sqrt(m.score));
  }
  const double n = static_cast<double>(matches.size());
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
