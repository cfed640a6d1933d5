#include "lab/report/run_plots.h"

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "lab/report/gnuplot.h"
#include "lab/report/text_format.h"
#include "mlndt/common/atomic_file.h"

namespace mlndt {

bool WriteOdometryPlot(const std::string& gnuplot,
                       const std::string& dir,
                       const std::vector<OdometryResult>& results,
                       const std::vector<Isometry3d>& reference,
                       std::string* error) {
  const std::string data_dir = dir + "/plot_data";
  std::filesystem::create_directories(data_dir);
  std::string estimate, fallbacks, truth;
  for (const OdometryResult& r : results) {
    const Vector3d& t = r.world_from_sensor.translation();
    const std::string line = Num(t.x()) + " " + Num(t.y()) + "\n";
    estimate += line;
    if (r.fallback) fallbacks += line;
  }
  if (!reference.empty()) {
    const Isometry3d first_inverse = reference.front().inverse();
    for (size_t k = 0; k < results.size() && k < reference.size(); ++k) {
      const Vector3d t = (first_inverse * reference[k]).translation();
      truth += Num(t.x()) + " " + Num(t.y()) + "\n";
    }
  }
  if (fallbacks.empty()) fallbacks = "NaN NaN\n";
  if (!WriteFileAtomically(data_dir + "/estimate.dat", estimate, error) ||
      !WriteFileAtomically(data_dir + "/fallbacks.dat", fallbacks, error) ||
      (!truth.empty() &&
       !WriteFileAtomically(data_dir + "/reference.dat", truth, error))) {
    return false;
  }
  const std::string png = dir + "/trajectory_xy.png";
  std::string script = GnuplotPngHeader(900, 700) + GnuplotSetOutput(png) +
                       "set size ratio -1\nset xlabel 'x [m]'\n"
                       "set ylabel 'y [m]'\nset title 'mlndt_odometry: top "
                       "view (first scan frame)' noenhanced\nplot " +
                       GnuplotQuote(data_dir + "/estimate.dat") +
                       " with linespoints pt 7 ps 0.4 title 'odometry', " +
                       GnuplotQuote(data_dir + "/fallbacks.dat") +
                       " with points pt 6 ps 1.5 lc rgb 'red' title "
                       "'prediction used (fallback)'";
  if (!truth.empty()) {
    script += ", " + GnuplotQuote(data_dir + "/reference.dat") +
              " with lines lc rgb 'black' title 'reference'";
  }
  script += "\n";
  return RunGnuplot(
      gnuplot, data_dir + "/trajectory_xy.gp", script, {png}, error);
}

bool WriteLocalizationPlot(const std::string& dir,
                           const LayeredGrid& map,
                           const std::vector<LocalizationResult>& results,
                           int plot_max_cells,
                           const std::string& gnuplot,
                           std::string* error) {
  std::string data_dir;
  if (!MakePlotDataDir(dir, &data_dir, error)) return false;
  const std::vector<NdtCell>& cells = map.layer(map.num_layers()).cells();
  const size_t max_cells = static_cast<size_t>(plot_max_cells);
  const size_t stride =
      max_cells == 0
          ? 0
          : std::max<size_t>(1, (cells.size() + max_cells - 1) / max_cells);
  {
    std::ostringstream out;
    out << "# x_m y_m z_m (finest-layer cell means, every " << stride
        << "-th)\n";
    for (size_t c = 0; stride > 0 && c < cells.size(); c += stride) {
      out << cells[c].mean.x() << " " << cells[c].mean.y() << " "
          << cells[c].mean.z() << "\n";
    }
    std::ostringstream trajectory;
    trajectory << "# x_m y_m converged(1/0)\n";
    for (const LocalizationResult& r : results) {
      trajectory << r.map_from_scan.translation().x() << " "
                 << r.map_from_scan.translation().y() << " "
                 << (r.registration.termination_type ==
                     TerminationType::CONVERGENCE)
                 << "\n";
    }
    if (!WriteFileAtomically(data_dir + "/map_cells.dat", out.str(), error) ||
        !WriteFileAtomically(
            data_dir + "/trajectory.dat", trajectory.str(), error)) {
      return false;
    }
  }
  std::ostringstream script;
  const std::string png = dir + "/trajectory_xy.png";
  script << GnuplotPngHeader(1000, 800) << GnuplotSetOutput(png)
         << "set title 'Map (finest cell means) and trajectory, top view'\n"
         << "set xlabel 'x [m]'\nset ylabel 'y [m]'\nset size ratio -1\n"
         << "plot " << GnuplotQuote(data_dir + "/map_cells.dat")
         << " using 1:2 with points pt 7 ps 0.3 lc rgb '#a0a0a0' title 'map "
            "cells', "
         << GnuplotQuote(data_dir + "/trajectory.dat")
         << " using 1:2 with linespoints lw 2 pt 7 ps 0.6 lc rgb '#c00000' "
            "title 'trajectory'\n";
  return RunGnuplot(gnuplot, data_dir + "/plot.gp", script.str(), {png}, error);
}

}  // namespace mlndt
