#include "mlndt/grid/cell_coverage.h"

namespace mlndt {

double CoveredPointFraction(const std::vector<int64_t>& cell_points,
                            int64_t min_points) {
  int64_t total = 0;
  int64_t covered = 0;
  for (int64_t count : cell_points) {
    total += count;
    if (count >= min_points) covered += count;
  }
  if (total == 0) return 0.0;
  return static_cast<double>(covered) / static_cast<double>(total);
}

}  // namespace mlndt
