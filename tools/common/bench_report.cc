#include "tools/common/bench_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "lab/eval/statistics.h"

namespace mlndt {
namespace tools {
namespace {

double Mean(const std::vector<double>& v) {
  if (v.empty()) return std::nan("");
  double sum = 0.0;
  for (const double x : v) sum += x;
  return sum / static_cast<double>(v.size());
}

double Median(const std::vector<double>& v) { return ComputeStats(v).median; }

// The round times' median, min and max, and the median over rounds of the
// per-round time ratio PCL / this method (NaN without PCL).
struct RowTimes {
  double median = 0.0, min = 0.0, max = 0.0;
  double pcl_ratio = std::nan("");
};

RowTimes TimesOf(const BenchMethodLabels& labels,
                 const BenchRowStats& s,
                 const BenchRowStats* pcl) {
  RowTimes t;
  t.median = Median(s.round_times_ms);
  t.min = *std::min_element(s.round_times_ms.begin(), s.round_times_ms.end());
  t.max = *std::max_element(s.round_times_ms.begin(), s.round_times_ms.end());
  if (pcl != nullptr && !labels.is_pcl) {
    std::vector<double> ratios;
    for (size_t r = 0; r < s.round_times_ms.size(); ++r) {
      ratios.push_back(pcl->round_times_ms[r] / s.round_times_ms[r]);
    }
    t.pcl_ratio = Median(ratios);
  }
  return t;
}

std::string Dash(const std::string& v) { return v.empty() ? "-" : v; }

// 6 significant digits; empty when not finite.
std::string CsvNumber(double v) {
  std::ostringstream out;
  out.precision(6);
  if (std::isfinite(v)) out << v;
  return out.str();
}

}  // namespace

BenchRowStats SummariseRuns(const std::vector<std::vector<BenchRun>>& results,
                            const std::vector<size_t>& pair_indices) {
  BenchRowStats s;
  std::vector<double> iterations, scores, translation, rotation, nees;
  for (const std::vector<BenchRun>& round : results) {
    std::vector<double> times, align;
    for (const size_t p : pair_indices) {
      const BenchRun& r = round[p];
      times.push_back(r.time_ms);
      align.push_back(r.align_ms);
      iterations.push_back(r.iterations);
      scores.push_back(r.score);
      translation.push_back(r.translation_error_m);
      rotation.push_back(r.rotation_error_deg);
      if (std::isfinite(r.nees)) nees.push_back(r.nees);
      ++s.runs;
      s.converged += r.converged;
      s.successes += r.success;
    }
    s.round_times_ms.push_back(Mean(times));
    s.round_align_ms.push_back(Mean(align));
  }
  s.mean_iterations = Mean(iterations);
  s.mean_score = Mean(scores);
  s.mean_translation_error_m = Mean(translation);
  s.max_translation_error_m =
      *std::max_element(translation.begin(), translation.end());
  s.mean_rotation_error_deg = Mean(rotation);
  if (!nees.empty()) {
    s.nees_mean = Mean(nees);
    s.nees_median = Median(nees);
  }
  s.max_rotation_error_deg =
      *std::max_element(rotation.begin(), rotation.end());
  return s;
}

BenchMethodLabels ConfigurationLabels(const BenchConfiguration& c) {
  const bool ceres_backend = c.backend == BackendType::CERES;
  BenchMethodLabels labels;
  labels.is_pcl = false;
  labels.method = "mlndt";
  labels.defaults = BenchDefaultsName(c.defaults);
  labels.backend = BackendFlagName(c.backend);
  labels.sampling = LowerCase(SamplingMethodToString(c.sampling));
  if (c.sampling == SamplingMethod::GBS) {
    labels.sampling += "_" + BenchFormat("%g", c.gbs_cell_size_m) + "m";
  }
  labels.start = std::to_string(c.start_layer);
  if (ceres_backend) {
    labels.solver = LowerCase(ceres::LinearSolverTypeToString(c.linear_solver));
    labels.region =
        LowerCase(ceres::TrustRegionStrategyTypeToString(c.trust_region));
  }
  labels.threads = std::to_string(c.threads);
  if (ceres_backend) {
    labels.minimizer = MinimizerFlagName(c);
    labels.jacobians = c.analytic_jacobians ? "analytic" : "autodiff";
    if (c.minimizer == ceres::LINE_SEARCH) labels.solver = labels.region = "";
  }
  labels.loss = LowerCase(LossTypeToString(c.loss));
  if (c.loss != LossType::NONE)
    labels.loss += "@" + BenchFormat("%g", c.loss_scale);
  return labels;
}

BenchMethodLabels PclLabels(double leaf_size_m) {
  BenchMethodLabels labels;
  labels.sampling = "voxel_grid_" + BenchFormat("%g", leaf_size_m);
  return labels;
}

std::string ShortLabel(const BenchMethodLabels& labels) {
  if (labels.is_pcl) return labels.method;
  std::string out;
  for (const std::string& part : {labels.backend,
                                  labels.minimizer,
                                  labels.jacobians,
                                  labels.loss,
                                  labels.solver,
                                  labels.region,
                                  labels.sampling,
                                  "s" + labels.start,
                                  "t" + labels.threads}) {
    if (!part.empty()) out += (out.empty() ? "" : " ") + part;
  }
  return out;
}

std::string BenchFormat(const char* format, double value) {
  if (!std::isfinite(value)) return "-";
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), format, value);
  return buffer;
}

std::vector<std::string> BenchTableHeader() {
  return {"pairs",         "defaults",
          "method",        "sampling",
          "start",         "linear solver",
          "trust region",  "minimizer",
          "jacobians",     "loss",
          "threads",       "runs",
          "time med [ms]", "time min-max [ms]",
          "iters",         "score",
          "err_t [m]",     "err_r [deg]",
          "converged",     "success",
          "nees mean/med", "pcl/ours"};
}

std::vector<std::string> BenchTableRow(const std::string& set,
                                       const BenchMethodLabels& labels,
                                       const BenchRowStats& s,
                                       const BenchRowStats* pcl) {
  const RowTimes t = TimesOf(labels, s, pcl);
  const double success_rate = static_cast<double>(s.successes) / s.runs;
  const std::string runs = std::to_string(s.runs);
  return {set,
          Dash(labels.defaults),
          labels.is_pcl ? labels.method : labels.backend,
          labels.sampling,
          Dash(labels.start),
          Dash(labels.solver),
          Dash(labels.region),
          Dash(labels.minimizer),
          Dash(labels.jacobians),
          Dash(labels.loss),
          labels.threads,
          runs,
          BenchFormat("%.1f", t.median),
          BenchFormat("%.1f", t.min) + "-" + BenchFormat("%.1f", t.max),
          BenchFormat("%.1f", s.mean_iterations),
          BenchFormat("%.1f", s.mean_score),
          BenchFormat("%.4f", s.mean_translation_error_m),
          BenchFormat("%.3f", s.mean_rotation_error_deg),
          std::to_string(s.converged) + "/" + runs,
          std::to_string(s.successes) + "/" + runs + " (" +
              BenchFormat("%.0f", 100.0 * success_rate) + "%)",
          BenchFormat("%.1f", s.nees_mean) + "/" +
              BenchFormat("%.1f", s.nees_median),
          BenchFormat("%.2f", t.pcl_ratio)};
}

std::string BenchCsvHeader() {
  return "pairs,defaults,method,backend,sampling,start_layer,linear_solver,"
         "trust_"
         "region,minimizer,jacobians,loss,threads,runs,"
         "time_median_ms,time_min_ms,time_max_ms,mean_iterations,mean_final_"
         "score,"
         "mean_translation_error_m,max_translation_error_m,mean_rotation_"
         "error_deg,"
         "max_rotation_error_deg,converged_rate,success_rate,nees_mean,nees_"
         "median,pcl_time_median_ms,pcl_over_ours\n";
}

std::string BenchCsvRow(const std::string& set,
                        const BenchMethodLabels& labels,
                        const BenchRowStats& s,
                        const BenchRowStats* pcl) {
  const RowTimes t = TimesOf(labels, s, pcl);
  const std::vector<std::string> values = {
      set,
      labels.defaults,
      labels.method,
      labels.backend,
      labels.sampling,
      labels.start,
      labels.solver,
      labels.region,
      labels.minimizer,
      labels.jacobians,
      labels.loss,
      labels.threads,
      std::to_string(s.runs),
      CsvNumber(t.median),
      CsvNumber(t.min),
      CsvNumber(t.max),
      CsvNumber(s.mean_iterations),
      CsvNumber(s.mean_score),
      CsvNumber(s.mean_translation_error_m),
      CsvNumber(s.max_translation_error_m),
      CsvNumber(s.mean_rotation_error_deg),
      CsvNumber(s.max_rotation_error_deg),
      CsvNumber(static_cast<double>(s.converged) / s.runs),
      CsvNumber(static_cast<double>(s.successes) / s.runs),
      CsvNumber(s.nees_mean),
      CsvNumber(s.nees_median),
      CsvNumber(pcl != nullptr ? Median(pcl->round_times_ms) : std::nan("")),
      CsvNumber(t.pcl_ratio)};
  std::string row;
  for (size_t c = 0; c < values.size(); ++c) row += (c ? "," : "") + values[c];
  return row;
}

void PrintMarkdownTable(const std::vector<std::vector<std::string>>& rows) {
  std::vector<size_t> widths(rows[0].size(), 3);
  for (const auto& row : rows) {
    for (size_t c = 0; c < row.size(); ++c)
      widths[c] = std::max(widths[c], row[c].size());
  }
  auto print_row = [&](const std::vector<std::string>& row) {
    std::string line = "|";
    for (size_t c = 0; c < row.size(); ++c) {
      line += " " + row[c] + std::string(widths[c] - row[c].size(), ' ') + " |";
    }
    std::cout << line << "\n";
  };
  print_row(rows[0]);
  std::string rule = "|";
  for (const size_t w : widths) rule += std::string(w + 2, '-') + "|";
  std::cout << rule << "\n";
  for (size_t r = 1; r < rows.size(); ++r) print_row(rows[r]);
}

}  // namespace tools
}  // namespace mlndt
