#pragma once

// All ML-NDT pair residuals of one pair (scan j's points against a layer of
// scan i's map, mlndt_pair_cost.h) as ONE residual block with the same
// Gauss-Newton normal equations, for pose graphs over many scans: a
// per-point block costs Ceres about 1 kB (block, functor, Jacobian, sparse
// structure; 1.2 GB for 933k blocks on 21 MulRan scans), this block costs
// its points (docs/embedding.md).
//
// With the robust loss applied per point as Ceres applies a LossFunction
// (Triggs' correction: r_k -> r~_k, J_k -> J~_k, ceres/loss_function.h), an
// evaluation with Jacobians sums the 15 x 15 Gram matrix
//
//   M = sum_k [J~_k r~_k]^T [J~_k r~_k]        (J~_k: 3 x 14 ambient)
//
// and returns a square root R of it, M = R^T R (symmetric eigensolver,
// R = Lambda^1/2 V^T): residuals 0..14 are R's last column, their Jacobian
// its first 14 columns, so J^T J = sum J~^T J~ and J^T r = sum J~^T r~ are
// exactly those of the per-point blocks, and so are the Gauss-Newton, LM
// and dogleg steps and Problem covariances. Residual 15 (Jacobian zero) is
// sqrt(sum rho_k - sum ||r~_k||^2), so that 1/2 ||r||^2 is the per-point
// blocks' cost 1/2 sum rho(s_k); the difference is >= 0 for the library's
// losses (NONE, HUBER, CAUCHY: concave rho gives rho(s) >= s rho'(s)).
// Evaluations without Jacobians return (sqrt(sum rho_k), 0, ..., 0). So
// the residual vector itself has no per-point meaning; its norm has.
//
// The points are copied (24 bytes each); the layer is fixed or read through
// a LayerBinding, which must outlive the Problem, as in mlndt_pair_cost.h.
// Bound, the block sums every binding.point_stride()-th point (all when
// fixed): SolveWithLayerSchedule thins coarse layers as Register does.
// Blocks: quaternion (x, y, z, w) and translation of world_from_scan_i and
// world_from_scan_j.

#include <ceres/loss_function.h>
#include <ceres/sized_cost_function.h>

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "mlndt/cost/layer_binding.h"
#include "mlndt/cost/objective_options.h"

namespace mlndt {

class MlNdtPairFactor : public ceres::SizedCostFunction<16, 4, 3, 4, 3> {
 public:
  // Every point's term is information_scale * rho(s) (w of
  // PairResidualOptions, add_pair_residuals.h).
  MlNdtPairFactor(LayerSource layer,
                  std::vector<Eigen::Vector3d> input_points_of_scan_j,
                  const ObjectiveOptions& objective,
                  double information_scale);
  ~MlNdtPairFactor() override;

  bool Evaluate(double const* const* parameters,
                double* residuals,
                double** jacobians) const override;

  size_t num_points() const { return points_.size(); }

 private:
  const LayerSource layer_;
  const std::vector<Eigen::Vector3d> points_;
  const UnmatchedPolicy policy_;
  const std::unique_ptr<ceres::LossFunction> loss_;  // nullptr: NONE.
  const double information_scale_;
};

}  // namespace mlndt
