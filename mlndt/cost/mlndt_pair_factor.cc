#include "mlndt/cost/mlndt_pair_factor.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <utility>

#include "mlndt/cost/internal/pair_jacobian.h"
#include "mlndt/cost/robust_loss.h"

namespace mlndt {
namespace {

using Gram = Eigen::Matrix<double, 15, 15>;

// rho(s), rho'(s), rho''(s) of `loss` (nullptr: s) times `scale`.
void EvaluateScaledLoss(const ceres::LossFunction* loss,
                        double scale,
                        double s,
                        double rho[3]) {
  if (loss == nullptr) {
    rho[0] = s;
    rho[1] = 1.0;
    rho[2] = 0.0;
  } else {
    loss->Evaluate(s, rho);
  }
  for (int k = 0; k < 3; ++k) rho[k] *= scale;
}

// Ceres' Corrector (internal/corrector.cc): the residual and Jacobian whose
// Gauss-Newton model is that of rho(||r||^2) (Triggs et al., Sec. 4.3).
void Correct(const double rho[3],
             Eigen::Vector3d* r,
             internal::PairJacobian* j) {
  const double sq_norm = r->squaredNorm();
  const double sqrt_rho1 = std::sqrt(rho[1]);
  if (sq_norm == 0.0 || rho[2] <= 0.0) {
    *r *= sqrt_rho1;
    *j *= sqrt_rho1;
    return;
  }
  const double alpha = 1.0 - std::sqrt(1.0 + 2.0 * sq_norm * rho[2] / rho[1]);
  *j = sqrt_rho1 * (*j - (alpha / sq_norm) * (*r) * (r->transpose() * *j));
  *r *= sqrt_rho1 / (1.0 - alpha);
}

// R with R^T R = gram (gram symmetric positive semi-definite).
Gram SquareRoot(const Gram& gram) {
  const Eigen::SelfAdjointEigenSolver<Gram> eigen(gram);
  const Eigen::Matrix<double, 15, 1> root =
      eigen.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  return root.asDiagonal() * eigen.eigenvectors().transpose();
}

}  // namespace

MlNdtPairFactor::MlNdtPairFactor(
    LayerSource layer,
    std::vector<Eigen::Vector3d> input_points_of_scan_j,
    const ObjectiveOptions& objective,
    double information_scale)
    : layer_(layer),
      points_(std::move(input_points_of_scan_j)),
      policy_(objective.unmatched_policy),
      loss_(CreateLoss(objective.loss, objective.loss_scale)),
      information_scale_(information_scale) {}

MlNdtPairFactor::~MlNdtPairFactor() = default;

bool MlNdtPairFactor::Evaluate(double const* const* parameters,
                               double* residuals,
                               double** jacobians) const {
  const internal::PairPoses poses(parameters);
  const NdtLayer& layer = layer_.layer();
  const bool with_jacobians = jacobians != nullptr;
  // Rows [J~_k r~_k] of kChunk points at a time, added to the Gram matrix
  // by one rank-k update (a blocked product; one rank-3 update per point
  // costs several times more).
  constexpr int kChunk = 128;
  Eigen::Matrix<double, 3 * kChunk, 15> rows;
  int filled = 0;
  Gram gram = Gram::Zero();
  const auto flush = [&] {
    gram.selfadjointView<Eigen::Upper>().rankUpdate(
        rows.topRows(3 * filled).transpose());
    filled = 0;
  };
  double rho_sum = 0.0;
  Eigen::Vector3d r;
  internal::PairJacobian j;
  const size_t stride = static_cast<size_t>(layer_.point_stride());
  for (size_t k = 0; k < points_.size(); k += stride) {
    if (!internal::PairResidual(layer,
                                policy_,
                                points_[k],
                                poses,
                                &r,
                                with_jacobians ? &j : nullptr)) {
      continue;  // Unmatched: zero residual, zero Jacobian, rho(0) = 0.
    }
    double rho[3];
    EvaluateScaledLoss(loss_.get(), information_scale_, r.squaredNorm(), rho);
    rho_sum += rho[0];
    if (!with_jacobians) continue;
    Correct(rho, &r, &j);
    rows.middleRows<3>(3 * filled) << j, r;
    if (++filled == kChunk) flush();
  }
  Eigen::Map<Eigen::Matrix<double, 16, 1>> out(residuals);
  out.setZero();
  if (!with_jacobians) {
    out(0) = std::sqrt(rho_sum);
    return true;
  }
  if (filled > 0) flush();
  gram.triangularView<Eigen::StrictlyLower>() = gram.transpose();
  const Gram root = SquareRoot(gram);
  out.head<15>() = root.col(14);
  out(15) = std::sqrt(std::max(0.0, rho_sum - gram(14, 14)));
  using RowMajor16 = Eigen::Matrix<double, 16, Eigen::Dynamic, Eigen::RowMajor>;
  const int offsets[] = {0, 4, 7, 11};
  const int sizes[] = {4, 3, 4, 3};
  for (int b = 0; b < 4; ++b) {
    if (jacobians[b] == nullptr) continue;
    Eigen::Map<RowMajor16> block(jacobians[b], 16, sizes[b]);
    block.topRows<15>() = root.middleCols(offsets[b], sizes[b]);
    block.row(15).setZero();
  }
  return true;
}

}  // namespace mlndt
