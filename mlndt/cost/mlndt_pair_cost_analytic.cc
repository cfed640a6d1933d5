#include "mlndt/cost/mlndt_pair_cost_analytic.h"

#include "mlndt/cost/internal/pair_jacobian.h"

namespace mlndt {

bool MlNdtPairCostAnalytic::Evaluate(double const* const* parameters,
                                     double* residuals,
                                     double** jacobians) const {
  const internal::PairPoses poses(parameters);
  Eigen::Vector3d r;
  internal::PairJacobian j;
  internal::PairResidual(layer_.layer(),
                         policy_,
                         input_point_,
                         poses,
                         &r,
                         jacobians != nullptr ? &j : nullptr);
  Eigen::Map<Eigen::Vector3d> out(residuals);
  out = r;
  if (jacobians == nullptr) return true;
  using RowMajor3 = Eigen::Matrix<double, 3, Eigen::Dynamic, Eigen::RowMajor>;
  const int offsets[] = {0, 4, 7, 11};
  const int sizes[] = {4, 3, 4, 3};
  for (int b = 0; b < 4; ++b) {
    if (jacobians[b] == nullptr) continue;
    Eigen::Map<RowMajor3>(jacobians[b], 3, sizes[b]) =
        j.middleCols(offsets[b], sizes[b]);
  }
  return true;
}

}  // namespace mlndt
