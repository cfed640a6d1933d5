#pragma once

// How much of a cloud the finest layer can describe: the fraction of the
// points that lie in cells holding enough points for a covariance (ML-NDT
// Section 4: a cell keeps a distribution, Eqs. 2-3, only with "more than 4"
// points). It sizes the finest layer from the data (LayeredGridOptions::
// min_covered_fraction): a sparse cloud (a solid-state keyframe, a thinned
// scan) whose points mostly fall in cells too sparse for Eq. (3) gets cells
// twice as large until enough of it is described.

#include <cstdint>
#include <vector>

namespace mlndt {

// The fraction of the points in cells with at least `min_points` points;
// `cell_points` holds each occupied cell's point count. 0 when there are no
// points.
double CoveredPointFraction(const std::vector<int64_t>& cell_points,
                            int64_t min_points);

}  // namespace mlndt
