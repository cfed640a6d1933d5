#pragma once

// The conventional NDT baseline as an Objective for MinimizeNewton
// (solvers/objective.h): the Gaussian score of ML-NDT Eq. (4) with
// Magnusson's outlier mixture on a single grid (gaussian_score.h).
// Lower is better: the score is the negated sum of -d1 exp(-d2 q / 2).

#include <vector>

#include "mlndt/grid/ndt_layer.h"
#include "mlndt/ndt/gaussian_score.h"
#include "mlndt/solvers/objective.h"

namespace mlndt {

// Keeps references: the grid and the points must outlive the objective.
class NdtGaussianObjective : public Objective {
 public:
  NdtGaussianObjective(const NdtLayer& grid,
                       const std::vector<Eigen::Vector3d>& input_points,
                       const GaussianScoreOptions& options)
      : grid_(grid), input_points_(input_points), options_(options) {}

  ScoreEvaluation Evaluate(const Vector6d& reference_from_input_xi,
                           HessianType hessian) const override {
    GaussianScoreOptions options = options_;
    options.hessian = hessian;
    return EvaluateGaussianScore(
        grid_, input_points_, reference_from_input_xi, options);
  }

 private:
  const NdtLayer& grid_;
  const std::vector<Eigen::Vector3d>& input_points_;
  const GaussianScoreOptions options_;
};

}  // namespace mlndt
