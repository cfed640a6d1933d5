#include "lab/experiments/sampling_section.h"

#include <cmath>

#include "lab/report/text_format.h"

namespace mlndt {
namespace experiments {
namespace {

struct Share {
  size_t runs = 0, right = 0;
  double time_ms = 0.0;
};

Share Measure(const ReportContext& c,
              const std::string& config,
              double fraction,
              const std::string& start) {
  Share s;
  for (const RunRecord* r : Select(c, "sampling", "", config)) {
    if (std::abs(r->parameter - fraction) > 1e-12 || r->start != start)
      continue;
    ++s.runs;
    s.right += r->right;
    s.time_ms += r->time_ms;
  }
  if (s.runs) s.time_ms /= s.runs;
  return s;
}

}  // namespace

std::string SamplingSection(const ReportContext& c) {
  const std::vector<std::pair<std::string, std::string>> configs = {
      {"ndt", "NDT"},
      {"paper", "ML-NDT paper preset"},
      {"defaults", "ML-NDT defaults"}};
  std::string out =
      "## Sampling fraction sweep: \"10–20 % of the input is sufficient\"\n\n"
      "Each data set's smallest-step pairs with a fraction of the input "
      "drawn uniformly at random (seed 1), from the identity and from the "
      "prior. Cells: runs within the strict tolerance, and the mean time "
      "[ms]. Pooled over every data set.\n\n";
  std::vector<std::string> header = {"fraction"};
  for (const std::string start : {"identity", "prior"}) {
    for (const auto& [key, label] : configs) {
      header.push_back(label + " from " + start);
      header.push_back("[ms]");
    }
  }
  std::vector<std::vector<std::string>> rows, curve;
  for (const double f : c.plan.fractions) {
    std::vector<std::string> row = {Fmt(100 * f, 0) + " %"};
    std::vector<std::string> point = {Num(100 * f)};
    for (const std::string start : {"identity", "prior"}) {
      for (const auto& [key, label] : configs) {
        const Share s = Measure(c, key, f, start);
        row.push_back(Percent(s.right, s.runs));
        row.push_back(Fmt(s.time_ms, 0));
        point.push_back(Num(PercentValue(s.right, s.runs)));
      }
    }
    rows.push_back(row);
    curve.push_back(point);
  }
  c.files->Add("csv/sampling.csv", CsvTable(header, rows));
  std::vector<std::string> curve_header = {"fraction_percent"};
  for (const std::string start : {"identity", "prior"}) {
    for (const auto& [key, label] : configs)
      curve_header.push_back(label + " from " + start);
  }
  c.files->Add("csv/sampling_curve.csv", CsvTable(curve_header, curve));
  out += MarkdownTable(header, rows);
  const std::string body =
      "set key autotitle columnheader\n"
      "set title 'Runs within tolerance against the sampled fraction (all "
      "data sets)'\nset xlabel 'input sampled at random [%]'\n"
      "set ylabel 'runs within tolerance [%]'\nset logscale x\n"
      "set xrange [0.8:40]\nset yrange [0:105]\n"
      "set xtics (1, 2, 5, 10, 20, 30)\n"
      "plot for [i=2:4] 'csv/sampling_curve.csv' using 1:i with "
      "linespoints lw 2 dt 1, for [i=5:7] 'csv/sampling_curve.csv' using "
      "1:i with linespoints lw 2 dt 2\n";
  out += "![sampling](" + c.files->AddFigure("sampling", 1200, 500, body) +
         ")\n\n";
  // The smallest fraction at which each ML-NDT configuration is within 5
  // points of its best, from the prior.
  out += "**Conclusion (this run):** from the prior, ";
  for (size_t i = 1; i < configs.size(); ++i) {
    double best = 0.0;
    for (const double f : c.plan.fractions) {
      const Share s = Measure(c, configs[i].first, f, "prior");
      best = std::max(best, PercentValue(s.right, s.runs));
    }
    std::string enough = "–";
    for (const double f : c.plan.fractions) {
      const Share s = Measure(c, configs[i].first, f, "prior");
      if (s.runs && PercentValue(s.right, s.runs) >= best - 5.0) {
        enough = Fmt(100 * f, 0) + " %";
        break;
      }
    }
    out += (i > 1 ? "; " : "") + configs[i].second +
           " is within 5 points of its best share (" + Fmt(best, 1) +
           " %) from " + enough + " of the input";
  }
  out += " (the paper: 10–20 % suffices).\n\n";
  return out;
}

}  // namespace experiments
}  // namespace mlndt
