#include "lab/experiments/scaling_report.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "lab/report/gnuplot.h"
#include "lab/report/text_format.h"
#include "mlndt/common/atomic_file.h"

namespace mlndt {

double LogLogSlope(const std::vector<double>& x, const std::vector<double>& y) {
  if (x.size() < 2 || x.size() != y.size()) return std::nan("");
  double mx = 0.0, my = 0.0;
  for (size_t i = 0; i < x.size(); ++i) {
    if (!(x[i] > 0) || !(y[i] > 0)) return std::nan("");
    mx += std::log(x[i]);
    my += std::log(y[i]);
  }
  mx /= x.size();
  my /= x.size();
  double sxy = 0.0, sxx = 0.0;
  for (size_t i = 0; i < x.size(); ++i) {
    sxy += (std::log(x[i]) - mx) * (std::log(y[i]) - my);
    sxx += (std::log(x[i]) - mx) * (std::log(x[i]) - mx);
  }
  return sxy / sxx;
}

std::vector<std::pair<std::string, std::vector<double>>> ScalingSeries(
    const std::vector<SizeResult>& results) {
  std::vector<std::pair<std::string, std::vector<double>>> series = {
      {"map", {}},
      {"sampling", {}},
      {"solve", {}},
      {"total", {}},
      {"sampled points", {}},
      {"finest-layer cells", {}}};
  for (const SizeResult& r : results) {
    series[0].second.push_back(r.map_ms);
    series[1].second.push_back(r.sampling_ms);
    series[2].second.push_back(r.solve_ms);
    series[3].second.push_back(r.total_ms);
    series[4].second.push_back(static_cast<double>(r.sampled_points));
    series[5].second.push_back(static_cast<double>(r.finest_cells));
  }
  return series;
}

bool WriteScalingCsv(const std::string& path,
                     const std::vector<SizeResult>& results,
                     std::string* error) {
  std::ostringstream out;
  out << "points,map_ms,sampling_ms,solve_ms,total_ms,sampled_points,finest_"
         "layer_cells,"
         "num_layers,iterations,termination,translation_error_m,rotation_error_"
         "deg,ok\n";
  for (const SizeResult& r : results) {
    out << r.points << "," << Num(r.map_ms) << "," << Num(r.sampling_ms) << ","
        << Num(r.solve_ms) << "," << Num(r.total_ms) << "," << r.sampled_points
        << "," << r.finest_cells << "," << r.num_layers << "," << r.iterations
        << "," << TerminationTypeToString(r.termination) << ","
        << Num(r.translation_error_m) << "," << Num(r.rotation_error_deg) << ","
        << (r.ok ? 1 : 0) << "\n";
  }
  return WriteFileAtomically(path, out.str(), error);
}

bool WriteScalingPlot(const std::string& gnuplot,
                      const std::string& dir,
                      const std::string& title,
                      const std::vector<SizeResult>& results,
                      const std::vector<double>& slopes,
                      std::string* error) {
  const std::string csv = GnuplotQuote(dir + "/scaling.csv");
  // The slope-1 line through the smallest size's total.
  const double per_point_ms =
      results.front().total_ms / static_cast<double>(results.front().points);
  std::ostringstream script;
  script
      << GnuplotPngHeader(900, 600) << GnuplotSetOutput(dir + "/scaling.png")
      << "set title '" << title << "'\n"
      << "set logscale xy\nset format x '10^{%L}'\nset format y '10^{%L}'\n"
      << "set xlabel 'points N (reference = input size)'\nset ylabel 'time "
         "[ms]'\n"
      << "set key inside top left\nset datafile separator ','\n"
      << "set xrange [" << Num(results.front().points / 1.5) << ":"
      << Num(results.back().points * 1.5) << "]\n"
      << "linear(x) = " << Num(per_point_ms) << " * x\n"
      << "plot " << csv
      << " skip 1 using 1:2 with linespoints lw 2 pt 7 title 'map build (slope "
      << Fmt(slopes[0], 2) << ")', \\\n"
      << "     '' skip 1 using 1:3 with linespoints lw 2 pt 5 title 'sampling "
         "(slope "
      << Fmt(slopes[1], 2) << ")', \\\n"
      << "     '' skip 1 using 1:4 with linespoints lw 2 pt 9 title 'solve "
         "(slope "
      << Fmt(slopes[2], 2) << ")', \\\n"
      << "     '' skip 1 using 1:5 with linespoints lw 2 pt 11 title 'total "
         "(slope "
      << Fmt(slopes[3], 2) << ")', \\\n"
      << "     [" << Num(static_cast<double>(results.front().points)) << ":"
      << Num(static_cast<double>(results.back().points))
      << "] linear(x) with lines dashtype 2 lc rgb 'gray40' lw 1.5 title "
         "'slope 1 (∝ N)'\n";
  return RunGnuplot(gnuplot,
                    dir + "/scaling.gp",
                    script.str(),
                    {dir + "/scaling.png"},
                    error);
}

std::string ScalingTableText(const std::vector<SizeResult>& results) {
  std::string out =
      "| points | map ms | sampling ms | solve ms | total ms | sampled | "
      "finest-layer "
      "cells | layers | iterations | t error cm | r error deg | solve |\n"
      "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n";
  for (const SizeResult& r : results) {
    char row[512];
    std::snprintf(
        row,
        sizeof(row),
        "| %zu | %s | %s | %s | %s | %zu | %zu | %d | %d | %s | %s | %s |\n",
        r.points,
        Fmt(r.map_ms, 1).c_str(),
        Fmt(r.sampling_ms, 1).c_str(),
        Fmt(r.solve_ms, 1).c_str(),
        Fmt(r.total_ms, 1).c_str(),
        r.sampled_points,
        r.finest_cells,
        r.num_layers,
        r.iterations,
        Fmt(r.translation_error_m * 100.0, 2).c_str(),
        Fmt(r.rotation_error_deg, 3).c_str(),
        r.ok ? "ok"
             : (r.termination == TerminationType::FAILURE ? "FAILED"
                                                          : "LARGE ERROR"));
    out += row;
  }
  return out;
}

std::vector<double> ScalingSlopes(const std::vector<size_t>& sizes,
                                  const std::vector<SizeResult>& results) {
  std::vector<double> x;
  for (size_t n : sizes) x.push_back(static_cast<double>(n));
  std::vector<double> slopes;
  for (const auto& series : ScalingSeries(results)) {
    slopes.push_back(LogLogSlope(x, series.second));
  }
  return slopes;
}

std::string ScalingSlopesText(const std::vector<size_t>& sizes,
                              const std::vector<SizeResult>& results,
                              const std::vector<double>& slopes) {
  std::ostringstream out;
  out << "\nlog-log slope over N = " << sizes.front() << ".." << sizes.back()
      << " (time ∝ N^slope; 1 = linear):\n";
  const auto series = ScalingSeries(results);
  for (size_t k = 0; k < series.size() && k < slopes.size(); ++k) {
    char line[128];
    std::snprintf(line,
                  sizeof(line),
                  "  %-19s %s\n",
                  (series[k].first + ":").c_str(),
                  Fmt(slopes[k], 2).c_str());
    out << line;
  }
  // The solve's cost per residual: its time against the sampled points.
  std::vector<double> sampled, solve_ms;
  for (const SizeResult& r : results) {
    sampled.push_back(static_cast<double>(r.sampled_points));
    solve_ms.push_back(r.solve_ms);
  }
  out << "  solve against sampled points (time ∝ S^slope): "
      << Fmt(LogLogSlope(sampled, solve_ms), 2) << "\n";
  return out.str();
}

std::vector<std::string> BrokenSolveLines(
    const std::vector<SizeResult>& results,
    double max_translation_error_m,
    double max_rotation_error_deg) {
  std::vector<std::string> lines;
  for (const SizeResult& r : results) {
    if (r.ok) continue;
    lines.push_back(
        "N = " + std::to_string(r.points) + ": " +
        (r.termination == TerminationType::FAILURE
             ? "registration FAILED: " + r.message
             : "recovered motion off by " +
                   Fmt(r.translation_error_m * 100.0, 2) + " cm, " +
                   Fmt(r.rotation_error_deg, 3) + " deg (tolerance " +
                   Fmt(max_translation_error_m * 100.0, 1) + " cm, " +
                   Fmt(max_rotation_error_deg, 2) + " deg)"));
  }
  return lines;
}

std::string ScalingPlotTitle(int repetitions,
                             Method method,
                             const std::string& backend,
                             const std::string& sampling) {
  return "Registration time against cloud size (median of " +
         std::to_string(repetitions) + " runs; " + MethodToString(method) +
         ", " + backend + ", " + sampling + " sampling)";
}

std::string ScalingRunLine(Method method,
                           const std::string& backend,
                           const std::string& sampling,
                           int threads,
                           const std::string& motion,
                           int repetitions) {
  return std::string(MethodToString(method)) + ", backend " + backend +
         ", sampling " + sampling + ", threads " + std::to_string(threads) +
         "; motion " + motion + "; median of " + std::to_string(repetitions) +
         " runs";
}

}  // namespace mlndt
