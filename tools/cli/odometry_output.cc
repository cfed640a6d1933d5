#include "tools/cli/odometry_output.h"

#include <cstdio>
#include <filesystem>

#include "lab/eval/statistics.h"
#include "lab/report/gnuplot.h"
#include "lab/report/text_format.h"
#include "mlndt/common/atomic_file.h"
#include "mlndt/common/pose.h"
#include "mlndt/odometry/run_odometry.h"
#include "tools/cli/scan_files.h"
#include "tools/cli/tool_utils.h"

namespace mlndt {
namespace tools {
bool WriteOdometryFiles(const std::string& dir,
                        const ScanInput& input,
                        const std::vector<OdometryResult>& results,
                        std::string* error) {
  return WriteScanFilesOf(
      dir,
      "mlndt_odometry",
      input,
      OdometryResultTable(),
      results,
      [](const OdometryResult& r) {
        return ScanPose{r.index, r.stamp_s, r.world_from_sensor};
      },
      error);
}

Json OdometrySummaryJson(const OdometrySummary& summary,
                         const std::vector<OdometryResult>& results,
                         const OdometryMetrics* metrics) {
  Json json = ToolJson("mlndt_odometry");
  json["scans"] = summary.scans;
  // As mlndt_localize's and mlndt_sequence's summary.json.
  json["terminations"] = {{"CONVERGENCE", summary.convergence},
                          {"NO_CONVERGENCE", summary.no_convergence},
                          {"LOW_QUALITY", summary.low_quality},
                          {"DEGENERATE", summary.degenerate},
                          {"FAILURE", summary.failure}};
  json["fallbacks"] = summary.fallbacks;
  json["keyframes"] = summary.keyframes;
  json["recovery"] = {
      {"searched", summary.searched},
      {"recovered", summary.recovered},
      {"interpolated", summary.interpolated},
      {"extrapolated", summary.fallbacks - summary.interpolated}};
  std::vector<double> total_ms;
  for (const OdometryResult& r : results)
    total_ms.push_back(r.total_time_s * 1e3);
  json["time_ms_stats"] = {{"scan", StatsJson(ComputeStats(total_ms))}};
  if (metrics == nullptr) return json;
  json["metrics"] = {
      {"ate_se3_rmse_m", Number(metrics->ate.rmse_m)},
      {"ate_se3_max_m", Number(metrics->ate.errors.max)},
      {"rpe_delta_scans", metrics->rpe_delta},
      {"rpe_translation_rmse_m", Number(metrics->rpe.translation_rmse_m)},
      {"rpe_rotation_rmse_deg", Number(metrics->rpe.rotation_rmse_deg)},
      {"segments", KittiLengthsJson(metrics->segments.lengths)}};
  return json;
}

void PrintOdometrySummary(const OdometrySummary& summary,
                          const std::vector<OdometryResult>& results,
                          const OdometryMetrics* metrics) {
  std::vector<double> total_ms;
  for (const OdometryResult& r : results)
    total_ms.push_back(r.total_time_s * 1e3);
  const Stats t = ComputeStats(total_ms);
  std::printf(
      "scans: %zu; CONVERGENCE %zu, NO_CONVERGENCE %zu, LOW_QUALITY %zu, "
      "DEGENERATE %zu, FAILURE %zu; keyframes %zu\nnot registered from the "
      "prediction: searched %zu, recovered %zu; without a registered pose "
      "(fallback) %zu: interpolated %zu, extrapolated %zu\ntime per scan "
      "[ms]: mean %.1f, median %.1f, max %.1f\n",
      summary.scans,
      summary.convergence,
      summary.no_convergence,
      summary.low_quality,
      summary.degenerate,
      summary.failure,
      summary.keyframes,
      summary.searched,
      summary.recovered,
      summary.fallbacks,
      summary.interpolated,
      summary.fallbacks - summary.interpolated,
      t.mean,
      t.median,
      t.max);
  if (metrics == nullptr) return;
  std::printf("ATE (SE3-aligned): rmse %.3f m, max %.3f m\n",
              metrics->ate.rmse_m,
              metrics->ate.errors.max);
  std::printf(
      "RPE over %d scans%s: translation rmse %.3f m, rotation rmse %.3f "
      "deg\n",
      metrics->rpe_delta,
      metrics->rpe_delta == metrics->rpe_delta_asked
          ? ""
          : (" (--rpe_delta=" + std::to_string(metrics->rpe_delta_asked) +
             " is longer than the run)")
                .c_str(),
      metrics->rpe.translation_rmse_m,
      metrics->rpe.rotation_rmse_deg);
  for (const KittiLengthErrors& l : metrics->segments.lengths) {
    std::printf(
        "KITTI segments of %.0f m (%zu): translation %.2f %%, rotation "
        "%.4f deg/m\n",
        l.length_m,
        l.num_segments,
        l.translation_error_percent,
        l.rotation_error_deg_per_m);
  }
}

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

}  // namespace tools
}  // namespace mlndt
