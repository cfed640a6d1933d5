#include "mlndt/common/result_table.h"
#include "mlndt/cost/fit_quality.h"

namespace mlndt {

const ResultTable& FitQualityTable() {
  static const ResultTable table =
      ResultTableBuilder<FitQuality>("FitQuality")
          .Integer("points",
                   &FitQuality::points,
                   "",
                   "Sampled input points the fit was evaluated on.")
          .Number("own_cell_fraction",
                  &FitQuality::own_cell_fraction,
                  "",
                  "Share of points whose own cell is occupied (the overlap).")
          .Number("inlier_fraction",
                  &FitQuality::inlier_fraction,
                  "",
                  "Share of points with s_k < gate^2 (a Mahalanobis gate).")
          .Number("mean_score",
                  &FitQuality::mean_score,
                  "",
                  "Mean of g^2 log(1 + s_k / g^2) over the matched points: a "
                  "Cauchy loss at the gate g.")
          .Number("median_distance",
                  &FitQuality::median_distance,
                  "sigma",
                  "Median Mahalanobis distance sqrt(s_k) of the matched "
                  "points to their cells; the quality check's main measure.")
          .Build();
  return table;
}

}  // namespace mlndt
