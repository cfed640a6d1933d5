#include "lab/experiments/table9_section.h"

#include <cmath>
#include <sstream>

#include "lab/experiments/paper_numbers.h"
#include "lab/report/text_format.h"

namespace mlndt {
namespace experiments {
namespace {

struct Cell {
  size_t runs = 0, diverged = 0;
  double time_ms = 0.0, error_cm = 0.0;  // Means (error: of the rest).
};

std::string StartLabel(double c) {
  std::ostringstream label;
  label << "c=" << c;
  return label.str();
}

Cell Measure(const ReportContext& ctx,
             const std::string& config,
             int layer,
             double c) {
  Cell cell;
  size_t kept = 0;
  for (const RunRecord* r : Select(ctx, "table9", "", config)) {
    if (static_cast<int>(r->parameter) != layer || r->start != StartLabel(c))
      continue;
    ++cell.runs;
    cell.time_ms += r->time_ms;
    if (r->diverged) {
      ++cell.diverged;
    } else {
      ++kept;
      cell.error_cm += 100.0 * r->translation_m;
    }
  }
  if (cell.runs) cell.time_ms /= cell.runs;
  cell.error_cm = kept ? cell.error_cm / kept : NAN;
  return cell;
}

// Working layers on n = 4 for the paper's rows.
std::string Working(int start_layer) {
  return start_layer == -2   ? "2, 3, 4 (n-2..n)"
         : start_layer == -1 ? "3, 4 (n-1..n)"
                             : "4 (n)";
}

}  // namespace

std::string Table9Section(const ReportContext& c) {
  std::string out =
      "## Table 9: initialisation and start layer (divergence)\n\n"
      "Every pair of the plan (largest steps first) started from Z_i = c "
      "Z_ref (c times the reference's six parameters), on the working "
      "layers n-2..n, n-1..n or n only. A run fails by the paper's rule: "
      "more than 1 m or 15° from the reference (the paper measures against "
      "its ground truth). Time: mean registration time [ms] (the paper: "
      "MATLAB seconds); error: mean translation error of the runs that did "
      "not fail [cm]. Pooled over every data set.\n\n";
  std::vector<std::vector<std::string>> rows;
  size_t paper_fail = 0, paper_runs = 0, defaults_fail = 0, defaults_runs = 0;
  for (const double z : c.plan.table9_c) {
    for (const int layer : c.plan.table9_start_layers) {
      std::vector<std::string> row = {Fmt(z, 1), Working(layer)};
      bool found = false;
      for (const PaperTable9Row& p : kPaperTable9) {
        if (std::abs(p.c - z) < 1e-9 && p.start_layer == 4 + layer) {
          row.push_back(Fmt(p.fail_percent, 0) + " %");
          row.push_back(Fmt(p.time_s, 2) + " s");
          row.push_back(Fmt(p.error_cm, 2));
          found = true;
        }
      }
      if (!found) row.insert(row.end(), {"–", "–", "–"});
      for (const std::string config : {"paper", "defaults"}) {
        const Cell cell = Measure(c, config, layer, z);
        row.push_back(Percent(cell.diverged, cell.runs));
        row.push_back(Fmt(cell.time_ms, 0));
        row.push_back(Fmt(cell.error_cm, 2));
        (config == std::string("paper") ? paper_fail : defaults_fail) +=
            cell.diverged;
        (config == std::string("paper") ? paper_runs : defaults_runs) +=
            cell.runs;
      }
      rows.push_back(row);
    }
  }
  const std::vector<std::string> header = {"Z_i / Z_ref",
                                           "working layers",
                                           "paper: fail",
                                           "paper: time",
                                           "paper: err [cm]",
                                           "paper preset: fail",
                                           "paper preset: [ms]",
                                           "paper preset: err [cm]",
                                           "defaults: fail",
                                           "defaults: [ms]",
                                           "defaults: err [cm]"};
  c.files->Add("csv/table9.csv", CsvTable(header, rows));
  out += MarkdownTable(header, rows);
  // The best start layer from Z_i = 0 under the paper preset.
  std::string best = "–";
  double best_fail = 2.0;
  for (const int layer : c.plan.table9_start_layers) {
    const Cell cell = Measure(c, "paper", layer, 0.0);
    if (cell.runs && double(cell.diverged) / cell.runs < best_fail) {
      best_fail = double(cell.diverged) / cell.runs;
      best = StartLayerLabel(layer);
    }
  }
  out +=
      "**Conclusion (this run):** over all cells the paper preset fails "
      "on " +
      Percent(paper_fail, paper_runs) + " and the defaults on " +
      Percent(defaults_fail, defaults_runs) + " of " +
      std::to_string(paper_runs) +
      " runs each; from Z_i = 0 the paper preset fails least when it "
      "starts on layer " +
      best + " (the paper: layer 2 or 3).\n\n";
  return out;
}

}  // namespace experiments
}  // namespace mlndt
