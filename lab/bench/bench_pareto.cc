#include "lab/bench/bench_pareto.h"

namespace mlndt {

std::vector<bool> ParetoFront(const std::vector<BenchPlotPoint>& points) {
  std::vector<bool> front(points.size(), true);
  for (size_t a = 0; a < points.size(); ++a) {
    for (size_t b = 0; b < points.size() && front[a]; ++b) {
      const BenchPlotPoint &p = points[a], &q = points[b];
      if (b == a || q.set != p.set) continue;
      const bool no_worse = q.time_ms <= p.time_ms && q.error_m <= p.error_m;
      const bool better = q.time_ms < p.time_ms || q.error_m < p.error_m;
      if (no_worse && better) front[a] = false;
    }
  }
  return front;
}

}  // namespace mlndt
