#include "lab/bench/bench_report.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "lab/eval/statistics.h"

namespace mlndt {
namespace {

// The row's times; the ratio against the peer for our rows only.
BenchRowTimes TimesOf(const BenchMethodLabels& labels,
                      const BenchRowStats& s,
                      const BenchRowStats* pcl) {
  return RowTimes(s, labels.is_pcl ? nullptr : pcl);
}

std::string Dash(const std::string& v) { return v.empty() ? "-" : v; }

// 6 significant digits; empty when not finite.
std::string CsvNumber(double v) {
  std::ostringstream out;
  out.precision(6);
  if (std::isfinite(v)) out << v;
  return out.str();
}

// The index of the peer whose time is the pcl/ours column's numerator: PCL
// GICP (the proxy of the fastest peers, docs/performance.md) when it ran,
// else PCL NDT; -1 when neither did.
int PclPeerIndex(const BenchResult& result) {
  for (const char* peer : {"pcl_gicp", "pcl_ndt"}) {
    for (size_t m = 0; m < result.methods.size(); ++m) {
      if (result.methods[m].method == peer) return static_cast<int>(m);
    }
  }
  return -1;
}

bool HasMethod(const BenchResult& result, const std::string& name) {
  for (const BenchMethodLabels& labels : result.methods) {
    if (labels.method == name) return true;
  }
  return false;
}

std::string JoinInts(const std::vector<int>& values) {
  std::string out;
  for (const int v : values)
    out += (out.empty() ? "" : ",") + std::to_string(v);
  return out;
}

std::string Preamble(const BenchOptions& options, const BenchResult& result) {
  std::ostringstream out;
  out << "mlndt_bench: " << options.rounds.repetitions << " round(s); "
      << result.num_configurations << " configuration(s)"
      << (HasMethod(result, "pcl_ndt") ? " + pcl::NDT" : "")
      << (HasMethod(result, "pcl_gicp") ? " + pcl::GICP" : "")
      << "; time = per round, mean time_ms.total over the set's pairs: "
         "median and min-max over rounds\n";
  for (size_t k = 0; k < result.sets.size(); ++k) {
    const std::string& set = result.sets[k];
    out << "  " << set << ": " << result.set_pairs[k] << " run(s) a round"
        << (set == "kitti"
                ? " (gaps " + JoinInts(options.pairs.kitti_gaps) + ")"
                : "")
        << "\n";
  }
  out << "\n";
  return out.str();
}

std::string Notes(const BenchOptions& options,
                  const BenchResult& result,
                  const std::vector<std::string>& notes) {
  std::ostringstream out;
  out << "\n- success: translation error < "
      << options.rounds.thresholds.max_translation_error_m
      << " m and rotation error < "
      << options.rounds.thresholds.max_rotation_error_deg << " deg\n"
      << "- converged: stopped on the convergence test, not on the "
         "iteration cap\n"
      << "- iters, score, err_t, err_r: means over runs; score is Eq. (10) "
         "on the last layer (mlndt only)\n"
      << "- nees: e^T P^-1 e of the usable runs against the reference, P = "
         "the registration covariance (6 if consistent)\n";
  if (HasMethod(result, "pcl_ndt") || HasMethod(result, "pcl_gicp")) {
    out << "- pcl/ours: median over rounds of the per-round time ratio "
        << (HasMethod(result, "pcl_gicp") ? "pcl_gicp" : "pcl_ndt")
        << " / ours; the PCL peers are single-threaded\n";
  }
  if (HasMethod(result, "pcl_gicp")) {
    out << "- pcl_gicp: single-threaded; its time covers filtering, "
           "setInputTarget/Source and align() (with the covariances)\n";
  }
  for (const std::string& note : notes) out << "- " << note << "\n";
  return out.str();
}

}  // namespace

std::vector<std::string> BenchTableHeader() {
  return {"pairs",         "defaults",
          "method",        "sampling",
          "start",         "linear solver",
          "trust region",  "minimizer",
          "jacobians",     "loss",
          "threads",       "runs",
          "time med [ms]", "time min-max [ms]",
          "iters",         "point iters",
          "score",         "err_t [m]",
          "err_r [deg]",   "converged",
          "success",       "nees mean/med",
          "pcl/ours"};
}

std::vector<std::string> BenchTableRow(const std::string& set,
                                       const BenchMethodLabels& labels,
                                       const BenchRowStats& s,
                                       const BenchRowStats* pcl) {
  const BenchRowTimes t = TimesOf(labels, s, pcl);
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
          BenchFormat("%.0f", s.mean_point_iterations),
          BenchFormat("%.1f", s.mean_score),
          BenchFormat("%.4f", s.mean_translation_error_m),
          BenchFormat("%.3f", s.mean_rotation_error_deg),
          std::to_string(s.converged) + "/" + runs,
          std::to_string(s.successes) + "/" + runs + " (" +
              BenchFormat("%.0f", 100.0 * success_rate) + "%)",
          BenchFormat("%.1f", s.nees_mean) + "/" +
              BenchFormat("%.1f", s.nees_median),
          BenchFormat("%.2f", t.reference_ratio)};
}

std::string BenchCsvHeader() {
  return "pairs,defaults,method,backend,sampling,start_layer,linear_solver,"
         "trust_"
         "region,minimizer,jacobians,loss,threads,runs,"
         "time_median_ms,time_min_ms,time_max_ms,mean_iterations,mean_point_"
         "iterations,mean_final_"
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
  const BenchRowTimes t = TimesOf(labels, s, pcl);
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
      CsvNumber(s.mean_point_iterations),
      CsvNumber(s.mean_score),
      CsvNumber(s.mean_translation_error_m),
      CsvNumber(s.max_translation_error_m),
      CsvNumber(s.mean_rotation_error_deg),
      CsvNumber(s.max_rotation_error_deg),
      CsvNumber(static_cast<double>(s.converged) / s.runs),
      CsvNumber(static_cast<double>(s.successes) / s.runs),
      CsvNumber(s.nees_mean),
      CsvNumber(s.nees_median),
      CsvNumber(pcl != nullptr ? RowTimes(*pcl, nullptr).median : std::nan("")),
      CsvNumber(t.reference_ratio)};
  std::string row;
  for (size_t c = 0; c < values.size(); ++c) row += (c ? "," : "") + values[c];
  return row;
}

std::string MarkdownTable(const std::vector<std::vector<std::string>>& rows) {
  std::vector<size_t> widths(rows[0].size(), 3);
  for (const auto& row : rows) {
    for (size_t c = 0; c < row.size(); ++c)
      widths[c] = std::max(widths[c], row[c].size());
  }
  std::string out;
  auto add_row = [&](const std::vector<std::string>& row) {
    out += "|";
    for (size_t c = 0; c < row.size(); ++c) {
      out += " " + row[c] + std::string(widths[c] - row[c].size(), ' ') + " |";
    }
    out += "\n";
  };
  add_row(rows[0]);
  out += "|";
  for (const size_t w : widths) out += std::string(w + 2, '-') + "|";
  out += "\n";
  for (size_t r = 1; r < rows.size(); ++r) add_row(rows[r]);
  return out;
}

std::string BenchReportText(const BenchOptions& options,
                            const BenchResult& result) {
  std::vector<std::vector<std::string>> table = {BenchTableHeader()};
  std::vector<std::string> notes;
  const int pcl = PclPeerIndex(result);
  for (size_t k = 0; k < result.sets.size(); ++k) {
    const std::vector<BenchRowStats>& stats = result.stats[k];
    for (size_t m = 0; m < stats.size(); ++m) {
      const BenchMethodLabels& labels = result.methods[m];
      table.push_back(BenchTableRow(
          result.sets[k], labels, stats[m], pcl < 0 ? nullptr : &stats[pcl]));
      if (labels.is_pcl) {
        notes.push_back(
            result.sets[k] + ": " + labels.method +
            " align() alone (without filtering and "
            "setInputTarget): median " +
            BenchFormat("%.1f", ComputeStats(stats[m].round_align_ms).median) +
            " ms");
      }
    }
  }
  return Preamble(options, result) + MarkdownTable(table) +
         Notes(options, result, notes);
}

std::string BenchCsvText(const BenchResult& result) {
  std::string csv = BenchCsvHeader();
  const int pcl = PclPeerIndex(result);
  for (size_t k = 0; k < result.sets.size(); ++k) {
    const std::vector<BenchRowStats>& stats = result.stats[k];
    for (size_t m = 0; m < stats.size(); ++m) {
      csv += BenchCsvRow(result.sets[k],
                         result.methods[m],
                         stats[m],
                         pcl < 0 ? nullptr : &stats[pcl]) +
             "\n";
    }
  }
  return csv;
}

std::vector<BenchPlotPoint> BenchPlotPoints(const BenchResult& result) {
  std::vector<BenchPlotPoint> points;
  for (size_t k = 0; k < result.sets.size(); ++k) {
    for (size_t m = 0; m < result.methods.size(); ++m) {
      const BenchRowStats& s = result.stats[k][m];
      points.push_back({result.sets[k],
                        ShortLabel(result.methods[m]),
                        RowTimes(s, nullptr).median,
                        s.mean_translation_error_m});
    }
  }
  return points;
}

}  // namespace mlndt
