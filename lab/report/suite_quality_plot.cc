#include "lab/report/suite_quality_plot.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <system_error>

#include "lab/report/gnuplot.h"
#include "lab/report/text_format.h"
#include "mlndt/common/atomic_file.h"

namespace mlndt {
namespace {

std::vector<double> Measure(
    const std::vector<std::vector<SuiteRunResult>>& results,
    bool right,
    double FitQuality::*field) {
  std::vector<double> values;
  for (const auto& set : results) {
    for (const SuiteRunResult& r : set) {
      const double v = r.registration.quality.*field;
      if (r.outcome.right == right && r.registration.quality.points > 0 &&
          std::isfinite(v)) {
        values.push_back(v);
      }
    }
  }
  std::sort(values.begin(), values.end());
  return values;
}

// "value share" lines of an empirical distribution curve.
bool WriteCurve(const std::string& path,
                const std::vector<double>& values,
                std::string* error) {
  std::ostringstream out;
  for (size_t k = 0; k < values.size(); ++k) {
    out << Num(values[k]) << " " << Num(double(k + 1) / values.size()) << "\n";
  }
  if (values.empty()) out << "nan nan\n";
  return WriteFileAtomically(path, out.str(), error);
}

}  // namespace

bool WriteSuiteQualityPlot(
    const std::string& gnuplot,
    const std::string& dir,
    const std::vector<std::vector<SuiteRunResult>>& results,
    const QualityCheckOptions* check,
    std::string* error) {
  const std::string data = dir + "/plot_data";
  std::error_code ec;
  std::filesystem::create_directories(data, ec);
  const auto path = [&](const char* name, bool right) {
    return data + "/" + name + (right ? "_right" : "_wrong") + ".txt";
  };
  size_t counts[2] = {0, 0};
  double distance_min = check ? check->max_median_distance : 1.0;
  double distance_max = distance_min;
  for (const bool right : {true, false}) {
    const std::vector<double> inliers =
        Measure(results, right, &FitQuality::inlier_fraction);
    const std::vector<double> distances =
        Measure(results, right, &FitQuality::median_distance);
    counts[right ? 0 : 1] = distances.size();
    for (const double v : distances) {
      if (v <= 0.0) continue;
      distance_min = std::min(distance_min, v);
      distance_max = std::max(distance_max, v);
    }
    if (!WriteCurve(path("inlier_fraction", right), inliers, error) ||
        !WriteCurve(path("median_distance", right), distances, error)) {
      return false;
    }
  }
  const auto curve = [&](const char* name, bool right) {
    const size_t n = counts[right ? 0 : 1];
    return GnuplotQuote(path(name, right)) + " using 1:2 with steps lw 2 " +
           "lc rgb '" + (right ? "#1a9850" : "#d73027") + "' title '" +
           (right ? "right" : "wrong") + " (" + std::to_string(n) + ")'";
  };
  const auto threshold = [&](int id, double x) {
    if (check == nullptr) return std::string();
    return "set arrow " + std::to_string(id) + " from " + Num(x) +
           ", graph 0 to " + Num(x) +
           ", graph 1 nohead dt 2 lw 1.5 lc rgb 'black'\n";
  };
  std::string script = GnuplotPngHeader(1200, 500);
  script += GnuplotSetOutput(dir + "/quality.png");
  script +=
      "set multiplot layout 1,2 title 'Fit at the solution of right "
      "and wrong runs: share of runs at or below a value (dashed: the "
      "quality check threshold)'\n";
  script += "set yrange [0:1.02]\nset ylabel 'share of runs'\n";
  script += "set key outside below horizontal\nset xrange [0:1]\n";
  script +=
      "set xlabel 'inlier fraction (Mahalanobis distance below the "
      "gate)'\n";
  if (check) script += threshold(1, check->min_inlier_fraction);
  script += "plot " + curve("inlier_fraction", true) + ", " +
            curve("inlier_fraction", false) + "\n";
  script += "unset arrow 1\nset logscale x\nset xtics 2\n";
  script += "set xrange [" + Num(distance_min / 1.5) + ":" +
            Num(distance_max * 1.5) + "]\n";
  script +=
      "set xlabel 'median Mahalanobis distance of the matched points "
      "(sigma)'\n";
  if (check) script += threshold(2, check->max_median_distance);
  script += "plot " + curve("median_distance", true) + ", " +
            curve("median_distance", false) + "\n";
  script += "unset multiplot\n";
  return RunGnuplot(
      gnuplot, data + "/quality.gp", script, {dir + "/quality.png"}, error);
}

}  // namespace mlndt
