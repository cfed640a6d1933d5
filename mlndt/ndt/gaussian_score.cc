#include "mlndt/ndt/gaussian_score.h"

#include <algorithm>
#include <cmath>

#include "mlndt/common/enum_table.h"
#include "mlndt/common/internal/check_option.h"
#include "mlndt/cost/internal/score_reduction.h"
#include "mlndt/cost/transform_derivatives.h"

namespace mlndt {
namespace {

// The face neighbours of DIRECT7, after the cell itself.
const Eigen::Vector3i kDirect7Offsets[7] = {Eigen::Vector3i(0, 0, 0),
                                            Eigen::Vector3i(1, 0, 0),
                                            Eigen::Vector3i(-1, 0, 0),
                                            Eigen::Vector3i(0, 1, 0),
                                            Eigen::Vector3i(0, -1, 0),
                                            Eigen::Vector3i(0, 0, 1),
                                            Eigen::Vector3i(0, 0, -1)};

// Adds one point-cell term of the score, gradient and Hessian (header).
void AddTerm(const NdtCell& cell,
             const Eigen::Vector3d& input_point,
             const Eigen::Vector3d& x,
             const TransformDerivatives& transform,
             const GaussianScoreParameters& p,
             HessianType hessian,
             ScoreEvaluation* sum) {
  const Eigen::Vector3d e = x - cell.mean;
  const Eigen::Vector3d information_e = cell.information * e;  // C^-1 e.
  const double q = e.dot(information_e);
  const double exponential = std::exp(-0.5 * p.d2 * q);
  if (!std::isfinite(exponential)) return;
  sum->score +=
      p.d1 * exponential;  // Eq. (4) as Magnusson's Eq. (6.9), negated.
  if (hessian == HessianType::NONE) return;
  const double w = -p.d1 * p.d2 * exponential;  // >= 0.
  const Eigen::Matrix<double, 3, 6> jacobian = transform.Jacobian(input_point);
  const Vector6d jt_information_e =
      jacobian.transpose() * information_e;  // J^T C^-1 e.
  // Eq. (6.12).
  sum->gradient.noalias() += w * jt_information_e;
  // Eq. (6.13): J^T C^-1 J, then the rank-one and transform second-order terms.
  sum->hessian.noalias() +=
      w * (jacobian.transpose() * cell.information * jacobian);
  if (hessian == HessianType::FULL) {
    sum->hessian.noalias() -=
        (w * p.d2) * (jt_information_e * jt_information_e.transpose());
    sum->hessian +=
        w * transform.WeightedSecondDerivative(input_point, information_e);
  }
}

void Accumulate(const NdtLayer& layer,
                const std::vector<Eigen::Vector3d>& points,
                size_t begin,
                size_t end,
                const TransformDerivatives& transform,
                const GaussianScoreParameters& parameters,
                const GaussianScoreOptions& options,
                ScoreEvaluation* sum) {
  const int num_offsets = options.neighbors == NdtNeighbors::DIRECT7 ? 7 : 1;
  for (size_t k = begin; k < end; ++k) {
    const Eigen::Vector3d& p = points[k];
    const Eigen::Vector3d x = transform.Transform(p);
    const Eigen::Vector3i ijk = layer.CellCoordinates(x);
    bool matched = false;
    for (int o = 0; o < num_offsets; ++o) {
      const NdtCell* cell = layer.CellAt(ijk + kDirect7Offsets[o]);
      if (cell == nullptr) continue;
      matched = true;
      AddTerm(*cell, p, x, transform, parameters, options.hessian, sum);
    }
    ++(matched ? sum->matched : sum->unmatched);
  }
}

}  // namespace

const EnumTable& NdtNeighborsTable() {
  static const EnumTable table({
      {static_cast<int>(NdtNeighbors::DIRECT1), "DIRECT1"},
      {static_cast<int>(NdtNeighbors::DIRECT7), "DIRECT7"},
  });
  return table;
}

const char* NdtNeighborsToString(NdtNeighbors neighbors) {
  return EnumToString(NdtNeighborsTable(), neighbors);
}

bool StringToNdtNeighbors(std::string value, NdtNeighbors* neighbors) {
  return StringToEnum(NdtNeighborsTable(), std::move(value), neighbors);
}

GaussianScoreParameters ComputeGaussianScoreParameters(double outlier_ratio,
                                                       double cell_size_m) {
  // Magnusson Eq. (6.8).
  const double c1 = 10.0 * (1.0 - outlier_ratio);
  const double c2 = outlier_ratio / (cell_size_m * cell_size_m * cell_size_m);
  GaussianScoreParameters p;
  p.d3 = -std::log(c2);
  p.d1 = -std::log(c1 + c2) - p.d3;
  p.d2 = -2.0 * std::log((-std::log(c1 * std::exp(-0.5) + c2) - p.d3) / p.d1);
  return p;
}

bool GaussianScoreOptions::IsValid(std::string* error) const {
  MLNDT_OPTION_GT(outlier_ratio, 0.0);
  MLNDT_OPTION_LT(outlier_ratio, 1.0);
  MLNDT_OPTION_GE(num_threads, 1);
  return true;
}

ScoreEvaluation EvaluateGaussianScore(
    const NdtLayer& layer,
    const std::vector<Eigen::Vector3d>& input_points,
    const Vector6d& reference_from_input_xi,
    const GaussianScoreOptions& options) {
  const TransformDerivatives transform(reference_from_input_xi);
  const GaussianScoreParameters parameters =
      ComputeGaussianScoreParameters(options.outlier_ratio, layer.cell_size());
  return internal::ReduceScoreInSlices(
      input_points.size(),
      std::max(1, options.num_threads),
      [&](size_t begin, size_t end, ScoreEvaluation* partial) {
        Accumulate(layer,
                   input_points,
                   begin,
                   end,
                   transform,
                   parameters,
                   options,
                   partial);
      });
}

}  // namespace mlndt
