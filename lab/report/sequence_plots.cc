#include "lab/report/sequence_plots.h"

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <system_error>

#include "lab/report/gnuplot.h"
#include "lab/report/text_format.h"
#include "mlndt/common/atomic_file.h"
#include "mlndt/common/pose.h"

namespace mlndt {
namespace {

// Where one figure's data and script lines go.
struct PlotFiles {
  std::string dir;       // The PNGs.
  std::string data_dir;  // dir/plot_data.
  std::string title_step;
  std::ostringstream* script;
  std::vector<std::string>* pngs;
};

bool ErrorPlots(const std::vector<PairResult>& results,
                const PlotFiles& f,
                std::string* error) {
  std::ostringstream errors;
  errors << "# input tx_cm ty_cm tz_cm alpha_deg beta_deg gamma_deg\n";
  for (const PairResult& r : results) {
    errors << r.input;
    for (int k = 0; k < 6; ++k) {
      errors << " " << Num(r.error.components(k) * (k < 3 ? 100.0 : kRadToDeg));
    }
    errors << "\n";
  }
  if (!WriteFileAtomically(f.data_dir + "/errors.dat", errors.str(), error)) {
    return false;
  }
  const std::string data = GnuplotQuote(f.data_dir + "/errors.dat");
  *f.script << GnuplotSetOutput(f.dir + "/errors_translation.png")
            << "set title 'Translation error per pair (" << f.title_step
            << ")'\n"
            << "set xlabel 'input scan index'\nset ylabel 'error [cm]'\n"
            << "plot " << data
            << " using 1:2 with linespoints title 't_x', '' using 1:3 with "
            << "linespoints title 't_y', '' using 1:4 with linespoints title "
               "'t_z'\n"
            << GnuplotSetOutput(f.dir + "/errors_rotation.png")
            << "set title 'Rotation error per pair (" << f.title_step << ")'\n"
            << "set ylabel 'error [deg]'\n"
            << "plot " << data
            << " using 1:5 with linespoints title 'alpha', '' using 1:6 with "
            << "linespoints title 'beta', '' using 1:7 with linespoints title "
               "'gamma'\n";
  f.pngs->push_back("errors_translation.png");
  f.pngs->push_back("errors_rotation.png");
  return true;
}

bool TrajectoryPlot(const std::vector<PairResult>& results,
                    size_t step,
                    bool has_truth,
                    const PlotFiles& f,
                    std::string* error) {
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
          f.data_dir + "/trajectory.dat", trajectory.str(), error)) {
    return false;
  }
  // Equal scales on both axes around the union of both paths.
  Eigen::AlignedBox2d box;
  for (const Isometry3d& p : estimate) box.extend(p.translation().head<2>());
  for (const Isometry3d& p : truth) box.extend(p.translation().head<2>());
  const double half = 0.55 * std::max(1.0, box.sizes().maxCoeff());
  const Eigen::Vector2d centre = box.center();
  const std::string data = GnuplotQuote(f.data_dir + "/trajectory.dat");
  std::ostringstream& script = *f.script;
  script << GnuplotSetOutput(f.dir + "/trajectory_xy.png")
         << "set title 'Trajectory, top view (" << f.title_step << ")'\n"
         << "set xlabel 'x [m]'\nset ylabel 'y [m]'\nset size ratio -1\nset "
            "key inside top left\n"
         << "set xrange [" << Num(centre.x() - half) << ":"
         << Num(centre.x() + half) << "]\n"
         << "set yrange [" << Num(centre.y() - half) << ":"
         << Num(centre.y() + half) << "]\n"
         << "plot " << data
         << " using 1:2 with linespoints title 'estimate (chained)'";
  if (has_truth) {
    script << ", '' using 3:4 with linespoints title 'ground truth'";
  }
  script << "\nset size noratio\nset autoscale xy\nset key outside right top\n";
  f.pngs->push_back("trajectory_xy.png");
  return true;
}

// Evenly spread pairs for the trace figure: first, ..., last.
std::vector<size_t> TracedPairs(size_t num_results, int trace_pairs) {
  std::vector<size_t> traced;
  const size_t count = std::min<size_t>(
      num_results, static_cast<size_t>(std::max(0, trace_pairs)));
  for (size_t k = 0; k < count; ++k) {
    traced.push_back(count == 1 ? 0 : k * (num_results - 1) / (count - 1));
  }
  return traced;
}

bool WriteTraceData(const std::vector<PairResult>& results,
                    const std::vector<size_t>& traced,
                    bool has_truth,
                    const std::string& path,
                    std::string* error) {
  std::ostringstream trace;
  trace << "# blocks per pair: iteration layer score_per_point "
           "translation_error_cm\n";
  for (size_t index : traced) {
    const PairResult& r = results[index];
    const double points = std::max<double>(
        1.0, static_cast<double>(r.registration.sampled_points));
    for (const IterationRecord& it : r.registration.trace) {
      const double error_cm =
          has_truth
              ? TranslationErrorM(
                    r.truth, PoseVectorToIsometry(it.reference_from_input_xi)) *
                    100.0
              : 0.0;
      trace << it.iteration << " " << it.layer << " " << Num(it.score / points)
            << " " << Num(error_cm) << "\n";
    }
    trace << "\n\n";
  }
  return WriteFileAtomically(path, trace.str(), error);
}

bool TracePlot(const std::vector<PairResult>& results,
               const std::vector<size_t>& traced,
               bool has_truth,
               const PlotFiles& f,
               std::string* error) {
  if (!WriteTraceData(
          results, traced, has_truth, f.data_dir + "/trace.dat", error)) {
    return false;
  }
  const std::string data = GnuplotQuote(f.data_dir + "/trace.dat");
  std::ostringstream& script = *f.script;
  script << GnuplotSetOutput(f.dir + "/score_vs_iteration.png");
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
      script << (k ? ", " : "") << data << " index " << k
             << " using 1:($4 > 0.01 ? $4 : 0.01) with linespoints title 'pair "
             << r.reference << "-" << r.input << "'";
    }
    script << "\nunset logscale y\nunset multiplot\n";
  }
  f.pngs->push_back("score_vs_iteration.png");
  return true;
}

}  // namespace

bool WriteSequencePlots(const std::string& gnuplot,
                        const std::string& dir,
                        const std::vector<PairResult>& results,
                        size_t step,
                        int trace_pairs,
                        std::vector<std::string>* pngs,
                        std::string* error) {
  std::string data_dir;
  if (!MakePlotDataDir(dir, &data_dir, error)) return false;
  const bool has_truth = !results.empty() && results.front().has_truth;
  std::ostringstream script;
  script << GnuplotPngHeader(1000, 560);
  const PlotFiles files{
      dir, data_dir, "step " + std::to_string(step), &script, pngs};
  if ((has_truth && !ErrorPlots(results, files, error)) ||
      !TrajectoryPlot(results, step, has_truth, files, error)) {
    return false;
  }
  const std::vector<size_t> traced = TracedPairs(results.size(), trace_pairs);
  if (!traced.empty() && !TracePlot(results, traced, has_truth, files, error)) {
    return false;
  }
  std::vector<std::string> figures;
  for (const std::string& png : *pngs) figures.push_back(dir + "/" + png);
  return RunGnuplot(
      gnuplot, data_dir + "/plots.gp", script.str(), figures, error);
}

}  // namespace mlndt
