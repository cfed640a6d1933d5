#pragma once

// What the hand-written minimisers minimise: a score of the pose vector xi
// with its gradient and Hessian. MlNdtObjective is ML-NDT's Mahalanobis sum
// on one layer (cost/score.h); the conventional NDT baseline provides the
// Gaussian score of Eq. (4) through the same interface (ndt/).

#include <vector>

#include "mlndt/common/types.h"
#include "mlndt/cost/scalar_residual.h"
#include "mlndt/cost/score.h"
#include "mlndt/grid/ndt_layer.h"

namespace mlndt {

class Objective {
 public:
  virtual ~Objective() = default;
  // Score at xi, with the requested Hessian (and the gradient unless NONE).
  virtual ScoreEvaluation Evaluate(const Vector6d& reference_from_input_xi,
                                   HessianType hessian) const = 0;
  // The paper's scalar-residual LM system at xi (scalar_residual.h); false
  // when the objective has none (the NDT baseline).
  virtual bool EvaluateScalarResiduals(const Vector6d& reference_from_input_xi,
                                       ScalarResidualSystem* system) const {
    (void)reference_from_input_xi;
    (void)system;
    return false;
  }
};

// Eq. (10) over `input_points` on `layer`. Keeps references: the layer and
// the points must outlive the objective.
class MlNdtObjective : public Objective {
 public:
  MlNdtObjective(const NdtLayer& layer,
                 const std::vector<Eigen::Vector3d>& input_points,
                 const ObjectiveOptions& objective,
                 int num_threads)
      : layer_(layer),
        input_points_(input_points),
        objective_(objective),
        num_threads_(num_threads) {}

  ScoreEvaluation Evaluate(const Vector6d& reference_from_input_xi,
                           HessianType hessian) const override {
    return EvaluateScore(layer_,
                         input_points_,
                         reference_from_input_xi,
                         objective_,
                         hessian,
                         num_threads_);
  }

  bool EvaluateScalarResiduals(const Vector6d& reference_from_input_xi,
                               ScalarResidualSystem* system) const override {
    *system = EvaluateScalarResidualSystem(
        layer_, input_points_, reference_from_input_xi, objective_);
    return true;
  }

 private:
  const NdtLayer& layer_;
  const std::vector<Eigen::Vector3d>& input_points_;
  const ObjectiveOptions objective_;
  const int num_threads_;
};

}  // namespace mlndt
