#pragma once

// How well the input points fit the reference map at a pose: the evidence a
// registration's verdict rests on (registration_summary.h). Evaluated on one
// layer (the finest, at the solution), over the sampled input points:
//
//   s_k = e_k^T C_k^-1 e_k   (Eq. 10) in the cell the objective's policy
//                            picks for point k (cell_match.h)
//
//   own_cell_fraction  share of points whose own cell is occupied (overlap)
//   inlier_fraction    share of points with s_k < gate^2 (a Mahalanobis gate)
//   mean_score         mean of g^2 log(1 + s_k / g^2) over matched points: a
//                      Cauchy loss at the gate g, whatever the objective's
//                      loss, so that the measure keeps its scale
//   median_distance    median of sqrt(s_k) over matched points

#include <vector>

#include "mlndt/common/types.h"
#include "mlndt/cost/objective_options.h"
#include "mlndt/cost/point_matches.h"
#include "mlndt/grid/ndt_layer.h"

namespace mlndt {

class ResultTable;

struct FitQuality {
  size_t points = 0;
  double own_cell_fraction = 0.0;
  double inlier_fraction = 0.0;
  double mean_score = 0.0;
  double median_distance = 0.0;
};

// FitQuality's fields: name, unit, help (result_table.h).
const ResultTable& FitQualityTable();

// `gate`: the Mahalanobis distance below which a point is an inlier (> 0).
// The objective gives the unmatched-point policy (which cell a point is
// scored in).
FitQuality EvaluateFitQuality(const NdtLayer& layer,
                              const std::vector<Eigen::Vector3d>& input_points,
                              const Vector6d& reference_from_input_xi,
                              const ObjectiveOptions& objective,
                              double gate);

// The same from points already matched at the pose (point_matches.h).
FitQuality FitQualityOf(const std::vector<PointMatch>& matches, double gate);

}  // namespace mlndt
