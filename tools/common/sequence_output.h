#pragma once

// Files written for a sequence run (mlndt_sequence): pairs.csv,
// summary.json, trace.csv, trajectories and gnuplot figures. The summary's
// numbers are computed from the same values pairs.csv holds (ComputeTotals),
// printed with 10 significant digits in both.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "mlndt/cloud/pose_io.h"
#include "mlndt/common/atomic_file.h"
#include "mlndt/common/pose.h"
#include "tools/common/gnuplot.h"
#include "tools/common/json_writer.h"
#include "tools/common/sequence_runner.h"

namespace mlndt {
namespace tools {

// A number for CSV and data files: 10 significant digits, "nan" when not
// finite.
inline std::string Num(double value) {
  if (!std::isfinite(value)) return "nan";
  char text[64];
  std::snprintf(text, sizeof(text), "%.10g", value);
  return text;
}

inline std::string CsvField(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string out = "\"";
  for (const char c : text) {
    out += c;
    if (c == '"') out += '"';
  }
  return out + "\"";
}

// pairs.csv: one row per pair. Error columns (signed components of the
// error transform, norms, success flags) are empty without ground truth.
inline bool WritePairsCsv(const std::string& path,
                          const ScanStore& store,
                          const std::vector<PairResult>& results,
                          std::string* error) {
  std::ostringstream out;
  out << "reference,input,reference_file,input_file,"
         "err_tx_cm,err_ty_cm,err_tz_cm,err_alpha_deg,err_beta_deg,err_gamma_"
         "deg,"
         "translation_error_cm,rotation_error_deg,success,strict_success,"
         "termination,iterations,start_layer,num_layers,sampled_points,"
         "time_total_ms,time_map_ms,time_sampling_ms,time_solve_ms,"
         "guess_deviation_m,guess_deviation_deg,guess_check_failed,running_"
         "fail_rate,"
         "est_tx_m,est_ty_m,est_tz_m,est_alpha_deg,est_beta_deg,est_gamma_"
         "deg\n";
  for (const PairResult& r : results) {
    out << r.reference << "," << r.input << ","
        << CsvField(store.file_name(r.reference)) << ","
        << CsvField(store.file_name(r.input)) << ",";
    if (r.has_truth) {
      for (int k = 0; k < 3; ++k)
        out << Num(r.error.components(k) * 100.0) << ",";
      for (int k = 3; k < 6; ++k)
        out << Num(r.error.components(k) * kRadToDeg) << ",";
      out << Num(r.error.translation_m * 100.0) << ","
          << Num(r.error.rotation_rad * kRadToDeg) << "," << int(r.success)
          << "," << int(r.strict_success) << ",";
    } else {
      out << ",,,,,,,,,,";
    }
    out << TerminationTypeToString(r.termination) << "," << r.iterations << ","
        << r.start_layer << "," << r.num_layers << "," << r.sampled_points
        << "," << Num(r.times.total_ms) << "," << Num(r.times.map_ms) << ","
        << Num(r.times.sampling_ms) << "," << Num(r.times.solve_ms) << ","
        << Num(r.guess_deviation_m) << "," << Num(r.guess_deviation_deg) << ","
        << int(r.guess_check_failed) << "," << Num(r.running_fail_rate);
    const Vector6d xi = IsometryToPoseVector(r.estimate);
    for (int k = 0; k < 6; ++k)
      out << "," << Num(k < 3 ? xi(k) : xi(k) * kRadToDeg);
    out << "\n";
  }
  return WriteFileAtomically(path, out.str(), error);
}

// trace.csv: every iteration of every pair.
inline bool WriteTraceCsv(const std::string& path,
                          const std::vector<PairResult>& results,
                          std::string* error) {
  std::ostringstream out;
  out << "reference,input,iteration,layer,score,step_norm,step_is_successful,"
         "tx_m,ty_m,tz_m,alpha_deg,beta_deg,gamma_deg,time_ms\n";
  for (const PairResult& r : results) {
    for (const IterationRecord& it : r.trace) {
      out << r.reference << "," << r.input << "," << it.iteration << ","
          << it.layer << "," << Num(it.score) << "," << Num(it.step_norm) << ","
          << int(it.step_is_successful);
      for (int k = 0; k < 6; ++k) {
        const double v = it.reference_from_input_xi(k);
        out << "," << Num(k < 3 ? v : v * kRadToDeg);
      }
      out << "," << Num(it.time_s * 1e3) << "\n";
    }
  }
  return WriteFileAtomically(path, out.str(), error);
}

inline std::string StatsJson(const Stats& s, bool with_quantiles) {
  JsonObject o;
  o.AddNumber("mean", s.mean).AddNumber("std", s.std).AddNumber("max", s.max);
  if (with_quantiles) o.AddNumber("median", s.median).AddNumber("p95", s.p95);
  return o.str();
}

inline std::string ErrorsJson(const std::vector<Stats>& errors) {
  JsonObject o;
  for (int k = 0; k < 8; ++k)
    o.Add(ErrorNames()[k], StatsJson(errors[k], false));
  return o.str();
}

// The run's totals as one JSON object; `header` holds the run's settings
// (raw JSON members) and comes first.
inline std::string SummaryJson(const JsonObject& header,
                               const std::vector<PairResult>& results) {
  const SequenceTotals t = ComputeTotals(results);
  JsonObject o = header;
  o.AddNumber("pairs", static_cast<double>(t.pairs))
      .AddBool("has_ground_truth", t.has_truth);
  if (t.has_truth) {
    o.AddString("success_rule",
                "translation error < 50 cm (the paper, Section 5.2.1)")
        .AddNumber("successes", static_cast<double>(t.successes))
        .AddNumber("success_rate_percent", t.success_rate_percent)
        .AddString("strict_success_rule",
                   "translation error < 20 cm and rotation error < 1 deg")
        .AddNumber("strict_successes", static_cast<double>(t.strict_successes))
        .AddNumber("strict_success_rate_percent", t.strict_success_rate_percent)
        .AddString(
            "errors_note",
            "|component| of the error transform truth^-1 * estimate (cm, deg), "
            "std = sample standard deviation")
        .Add("errors", ErrorsJson(t.errors))
        .Add("errors_successful_pairs", ErrorsJson(t.errors_successful));
  } else {
    o.Add("success_rate_percent", "null")
        .Add("strict_success_rate_percent", "null");
  }
  std::map<int, int> start_layers;
  for (const PairResult& r : results) ++start_layers[r.start_layer];
  JsonObject layers;
  for (const auto& [layer, count] : start_layers)
    layers.AddNumber(std::to_string(layer), count);
  o.AddNumber("registration_failures",
              static_cast<double>(t.registration_failures))
      .AddNumber("guess_check_failures",
                 static_cast<double>(t.guess_check_failures))
      .AddString("time_note",
                 "time_ms = map + registration per pair; p95 = nearest rank")
      .Add("time_ms", StatsJson(t.time_ms, true))
      .Add("map_time_ms", StatsJson(t.map_time_ms, true))
      .Add("registration_time_ms", StatsJson(t.registration_time_ms, true))
      .AddNumber("mean_iterations", t.iterations.mean)
      .Add("start_layer_counts", layers.str());
  return o.str();
}

// Figures of a sequence run, written into `dir` (data and scripts into
// dir/plot_data): errors_translation.png, errors_rotation.png (signed error
// components per input scan, like the paper's Figs. 14-16),
// trajectory_xy.png (top view against the ground truth) and
// score_vs_iteration.png (score per sampled point against the iteration
// for up to `trace_pairs` pairs, like Figs. 11 and 13, with the translation
// error along the way when the ground truth is known). `pngs` receives the
// file names written.
inline bool WriteSequencePlots(const std::string& gnuplot,
                               const std::string& dir,
                               const std::vector<PairResult>& results,
                               size_t step,
                               int trace_pairs,
                               std::vector<std::string>* pngs,
                               std::string* error) {
  namespace fs = std::filesystem;
  const std::string data_dir = dir + "/plot_data";
  std::error_code ec;
  fs::create_directories(data_dir, ec);
  if (ec) {
    *error = data_dir + ": " + ec.message();
    return false;
  }
  const bool has_truth = !results.empty() && results.front().has_truth;
  std::ostringstream script;
  script << GnuplotPngHeader(1000, 560);
  const std::string title_step = "step " + std::to_string(step);

  if (has_truth) {
    std::ostringstream errors;
    errors << "# input tx_cm ty_cm tz_cm alpha_deg beta_deg gamma_deg\n";
    for (const PairResult& r : results) {
      errors << r.input;
      for (int k = 0; k < 6; ++k) {
        errors << " "
               << Num(r.error.components(k) * (k < 3 ? 100.0 : kRadToDeg));
      }
      errors << "\n";
    }
    if (!WriteFileAtomically(data_dir + "/errors.dat", errors.str(), error)) {
      return false;
    }
    const std::string data = GnuplotQuote(data_dir + "/errors.dat");
    script << "set output " << GnuplotQuote(dir + "/errors_translation.png")
           << "\n"
           << "set title 'Translation error per pair (" << title_step << ")'\n"
           << "set xlabel 'input scan index'\nset ylabel 'error [cm]'\n"
           << "plot " << data
           << " using 1:2 with linespoints title 't_x', '' using 1:3 with "
           << "linespoints title 't_y', '' using 1:4 with linespoints title "
              "'t_z'\n"
           << "set output " << GnuplotQuote(dir + "/errors_rotation.png")
           << "\n"
           << "set title 'Rotation error per pair (" << title_step << ")'\n"
           << "set ylabel 'error [deg]'\n"
           << "plot " << data
           << " using 1:5 with linespoints title 'alpha', '' using 1:6 with "
           << "linespoints title 'beta', '' using 1:7 with linespoints title "
              "'gamma'\n";
    pngs->push_back("errors_translation.png");
    pngs->push_back("errors_rotation.png");
  }

  {
    std::ostringstream trajectory;
    trajectory << "# x_m y_m (estimate) [x_gt_m y_gt_m]\n";
    const std::vector<Isometry3d> estimate =
        ChainTrajectory(results, step, false);
    const std::vector<Isometry3d> truth =
        has_truth ? ChainTrajectory(results, step, true)
                  : std::vector<Isometry3d>();
    for (size_t k = 0; k < estimate.size(); ++k) {
      trajectory << Num(estimate[k].translation().x()) << " "
                 << Num(estimate[k].translation().y());
      if (has_truth) {
        trajectory << " " << Num(truth[k].translation().x()) << " "
                   << Num(truth[k].translation().y());
      }
      trajectory << "\n";
    }
    if (!WriteFileAtomically(
            data_dir + "/trajectory.dat", trajectory.str(), error)) {
      return false;
    }
    // Equal scales on both axes around the union of both paths.
    Eigen::AlignedBox2d box;
    for (const Isometry3d& p : estimate) box.extend(p.translation().head<2>());
    for (const Isometry3d& p : truth) box.extend(p.translation().head<2>());
    const double half = 0.55 * std::max(1.0, box.sizes().maxCoeff());
    const Eigen::Vector2d centre = box.center();
    const std::string data = GnuplotQuote(data_dir + "/trajectory.dat");
    script << "set output " << GnuplotQuote(dir + "/trajectory_xy.png") << "\n"
           << "set title 'Trajectory, top view (" << title_step << ")'\n"
           << "set xlabel 'x [m]'\nset ylabel 'y [m]'\nset size ratio -1\nset "
              "key inside top left\n"
           << "set xrange [" << Num(centre.x() - half) << ":"
           << Num(centre.x() + half) << "]\n"
           << "set yrange [" << Num(centre.y() - half) << ":"
           << Num(centre.y() + half) << "]\n"
           << "plot " << data
           << " using 1:2 with linespoints title 'estimate (chained)'";
    if (has_truth)
      script << ", '' using 3:4 with linespoints title 'ground truth'";
    script
        << "\nset size noratio\nset autoscale xy\nset key outside right top\n";
    pngs->push_back("trajectory_xy.png");
  }

  // Evenly spread pairs for the trace figure: first, ..., last.
  std::vector<size_t> traced;
  const size_t count = std::min<size_t>(
      results.size(), static_cast<size_t>(std::max(0, trace_pairs)));
  for (size_t k = 0; k < count; ++k) {
    traced.push_back(count == 1 ? 0 : k * (results.size() - 1) / (count - 1));
  }
  if (!traced.empty()) {
    std::ostringstream trace;
    trace << "# blocks per pair: iteration layer score_per_point "
             "translation_error_cm\n";
    for (size_t index : traced) {
      const PairResult& r = results[index];
      const double points =
          std::max<double>(1.0, static_cast<double>(r.sampled_points));
      for (const IterationRecord& it : r.trace) {
        const double error_cm =
            has_truth ? TranslationErrorM(
                            r.truth,
                            PoseVectorToIsometry(it.reference_from_input_xi)) *
                            100.0
                      : 0.0;
        trace << it.iteration << " " << it.layer << " "
              << Num(it.score / points) << " " << Num(error_cm) << "\n";
      }
      trace << "\n\n";
    }
    if (!WriteFileAtomically(data_dir + "/trace.dat", trace.str(), error)) {
      return false;
    }
    const std::string data = GnuplotQuote(data_dir + "/trace.dat");
    script << "set output " << GnuplotQuote(dir + "/score_vs_iteration.png")
           << "\n";
    if (has_truth) script << "set multiplot layout 2,1\n";
    script << "set title 'Score per sampled point against iteration (each on "
              "its own layer)'\n"
           << "set xlabel 'iteration'\nset ylabel 'score / point'\n"
           << "plot ";
    for (size_t k = 0; k < traced.size(); ++k) {
      const PairResult& r = results[traced[k]];
      script << (k ? ", " : "") << data << " index " << k
             << " using 1:3 with linespoints title 'pair " << r.reference << "-"
             << r.input << "'";
    }
    script << "\n";
    if (has_truth) {
      script << "set title 'Translation error against iteration'\n"
             << "set ylabel 'error [cm]'\nset logscale y\nplot ";
      for (size_t k = 0; k < traced.size(); ++k) {
        const PairResult& r = results[traced[k]];
        script
            << (k ? ", " : "") << data << " index " << k
            << " using 1:($4 > 0.01 ? $4 : 0.01) with linespoints title 'pair "
            << r.reference << "-" << r.input << "'";
      }
      script << "\nunset logscale y\nunset multiplot\n";
    }
    pngs->push_back("score_vs_iteration.png");
  }
  return RunGnuplot(gnuplot, data_dir + "/plots.gp", script.str(), error);
}

}  // namespace tools
}  // namespace mlndt
