#pragma once

// The score of conventional single-grid NDT, the baseline the paper compares
// ML-NDT against (ML-NDT Section 3, Eq. 4; Biber & Strasser; Magnusson's
// thesis, Chapter 6, P2D-NDT), with its analytic derivatives.
//
// Magnusson (Eq. 6.7) models a point x' = T(xi, x) near a cell (mean mu,
// covariance C) by a Gaussian mixed with a uniform outlier density,
//   p_bar(x') = -log(c1 exp(-q / 2) + c2),   q = e^T C^-1 e,  e = x' - mu,
//   c1 = 10 (1 - r),  c2 = r / k^3   (r: outlier ratio, k: cell edge [m]),
// and fits it with a Gaussian (Eq. 6.8), p_tilde = d1 exp(-d2 q / 2) + d3:
//   d3 = -log(c2),  d1 = -log(c1 + c2) - d3,
//   d2 = -2 log((-log(c1 exp(-1/2) + c2) - d3) / d1),
// so d1 < 0 < d2 for r in (0, 1). PCL's NormalDistributionsTransform uses the
// same constants (r = 0.55 by default, k = its resolution).
//
// Sign convention. The paper's Eq. (4) and PCL maximise
// sum exp(-q / 2)-like terms, -d1 exp(-d2 q / 2) > 0 per point. We MINIMISE
// the negative of that sum, like every other mlndt objective (lower is
// better):
//   score = sum_k sum_{j in cells(k)} d1 exp(-d2 q_kj / 2)            (<= 0)
// With w = -d1 d2 exp(-d2 q / 2) >= 0, J = d x' / d xi and
// H_E = d2 x' / d xi2 (transform_derivatives.h), per term (Magnusson
// Eqs. 6.12, 6.13, negated):
//   g += w J^T C^-1 e
//   H += w (J^T C^-1 J - d2 (J^T C^-1 e)(J^T C^-1 e)^T + sum_i (C^-1 e)_i
//   H_E,i)
//
// HessianType::FULL is this Newton Hessian (indefinite away from the
// minimum; the Newton minimiser lifts it). GAUSS_NEWTON keeps only the
// positive semi-definite part w J^T C^-1 J. NONE gives the score and counts
// only (no gradient).
//
// Which cells a point is scored in (NdtNeighbors): DIRECT1 is the cell
// holding x' only; DIRECT7 sums over that cell and its 6 face neighbours.
// Points with no occupied cell among them contribute nothing ("unmatched").

#include <Eigen/Core>
#include <string>
#include <vector>

#include "mlndt/common/types.h"
#include "mlndt/cost/score.h"
#include "mlndt/grid/ndt_layer.h"

namespace mlndt {

class EnumTable;

enum class NdtNeighbors {
  DIRECT1,  // The cell holding the point.
  DIRECT7,  // That cell and its 6 face neighbours.
};

// The names of NdtNeighbors's values (enum_table.h).
const EnumTable& NdtNeighborsTable();
const char* NdtNeighborsToString(NdtNeighbors neighbors);
bool StringToNdtNeighbors(std::string value, NdtNeighbors* neighbors);

// d1, d2 (and d3) of Magnusson Eq. (6.8).
struct GaussianScoreParameters {
  double d1 = 0.0;  // < 0.
  double d2 = 0.0;  // > 0.
  double d3 = 0.0;
};

// The constants for outlier ratio r in (0, 1) and cell edge k > 0 [m].
GaussianScoreParameters ComputeGaussianScoreParameters(double outlier_ratio,
                                                       double cell_size_m);

struct GaussianScoreOptions {
  // r: the share of the uniform outlier part, in (0, 1) (PCL: 0.55).
  double outlier_ratio = 0.55;
  NdtNeighbors neighbors = NdtNeighbors::DIRECT1;
  HessianType hessian = HessianType::FULL;
  // OpenMP threads over points. >= 1. The partial sums are reduced in a
  // fixed order, so a given thread count always gives the same bits.
  int num_threads = 1;

  bool IsValid(std::string* error) const;
};

// The score above for `input_points` moved by xi onto `layer`; d1, d2 from
// options.outlier_ratio and layer.cell_size(). ScoreEvaluation::matched
// counts points with at least one contributing cell.
ScoreEvaluation EvaluateGaussianScore(
    const NdtLayer& layer,
    const std::vector<Eigen::Vector3d>& input_points,
    const Vector6d& reference_from_input_xi,
    const GaussianScoreOptions& options);

}  // namespace mlndt
