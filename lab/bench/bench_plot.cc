#include "lab/bench/bench_plot.h"

#include <algorithm>
#include <numeric>
#include <sstream>

#include "lab/report/gnuplot.h"
#include "mlndt/common/atomic_file.h"

namespace mlndt {
namespace {

std::vector<std::string> Sets(const std::vector<BenchPlotPoint>& points) {
  std::vector<std::string> sets;
  for (const BenchPlotPoint& p : points) {
    if (std::find(sets.begin(), sets.end(), p.set) == sets.end())
      sets.push_back(p.set);
  }
  return sets;
}

// The data file: per set, its points sorted by time, blocks separated by
// two blank lines (gnuplot's `index`).
std::string DataText(const std::vector<BenchPlotPoint>& points,
                     const std::vector<bool>& front) {
  std::ostringstream out;
  out.precision(6);
  for (const std::string& set : Sets(points)) {
    std::vector<size_t> order;
    for (size_t k = 0; k < points.size(); ++k) {
      if (points[k].set == set) order.push_back(k);
    }
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
      return points[a].time_ms < points[b].time_ms;
    });
    out << "# " << set << "\n# time_ms error_m pareto label\n";
    for (const size_t k : order) {
      out << points[k].time_ms << " " << points[k].error_m << " "
          << (front[k] ? 1 : 0) << " \"" << points[k].label << "\"\n";
    }
    out << "\n\n";
  }
  return out.str();
}

std::string ScriptText(const std::string& png_path,
                       const std::vector<std::string>& sets) {
  const std::string data = GnuplotQuote(png_path + ".dat");
  std::ostringstream gp;
  gp << GnuplotPngHeader(1100, 420 * static_cast<int>(sets.size()))
     << GnuplotSetOutput(png_path)
     << "set termoption noenhanced\n"  // Names hold underscores.
     << "set logscale xy\n"            // Failed configurations are metres off.
     << "set multiplot layout " << sets.size() << ",1\n"
     << "set xlabel 'median time per registration [ms]'\n"
     << "set ylabel 'mean translation error [m]'\n";
  for (size_t i = 0; i < sets.size(); ++i) {
    gp << "set title "
       << GnuplotQuote(sets[i] +
                       ": one point per "
                       "configuration, Pareto front joined")
       << "\n"
       << "plot " << data << " index " << i
       << " using 1:2 with points pt 7 ps 0.8 lc rgb 'gray50' title "
          "'configuration', \\\n  "
       << data << " index " << i
       << " using 1:($3 > 0 ? $2 : 1/0) with linespoints pt 7 lw 2 lc rgb "
          "'red' title 'Pareto front', \\\n  "
       << data << " index " << i
       << " using 1:($3 > 0 ? $2 : 1/0):4 with labels offset 0.5,0.6 left "
          "font ',8' notitle\n";
  }
  gp << "unset multiplot\n";
  return gp.str();
}

}  // namespace

bool WriteBenchPlot(const std::string& gnuplot,
                    const std::string& png_path,
                    const std::vector<BenchPlotPoint>& points,
                    std::string* error) {
  if (!WriteFileAtomically(
          png_path + ".dat", DataText(points, ParetoFront(points)), error)) {
    return false;
  }
  return RunGnuplot(gnuplot,
                    png_path + ".gp",
                    ScriptText(png_path, Sets(points)),
                    {png_path},
                    error);
}

}  // namespace mlndt
