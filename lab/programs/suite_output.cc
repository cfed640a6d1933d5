#include "lab/programs/suite_output.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "lab/report/gnuplot.h"
#include "lab/report/suite_quality_plot.h"
#include "lab/report/text_format.h"
#include "mlndt/common/atomic_file.h"
#include "mlndt/common/pose.h"

namespace mlndt {
namespace lab {
namespace {

std::string CsvRow(const LoadedSuiteDataset& dataset,
                   const SuiteRun& run,
                   const SuiteRunResult& r) {
  const SuiteOutcome& o = r.outcome;
  const RegistrationSummary& s = r.registration;
  const PoseError start = ComputePoseError(run.reference_from_input,
                                           run.initial_reference_from_input);
  const Vector6d& e = o.error.components;
  std::vector<std::string> fields = {
      CsvField(dataset.dataset.name),
      run.pair_key,
      std::to_string(run.reference_index),
      std::to_string(run.input_index),
      std::to_string(run.input_index - run.reference_index),
      StartKindToString(run.kind),
      CsvField(run.start),
      Num(start.translation_m),
      Num(start.rotation_deg()),
      run.uncertainty.given ? Num(run.uncertainty.translation_m) : "",
      run.uncertainty.given ? Num(run.uncertainty.rotation_deg) : "",
      TerminationTypeToString(o.termination),
      CsvField(s.message),
      o.right ? "1" : "0",
      Num(o.error.translation_m),
      Num(o.error.rotation_deg()),
      Num(o.along_track_m),
      Num(e(0)),
      Num(e(1)),
      Num(e(2)),
      Num(e(3) * kRadToDeg),
      Num(e(4) * kRadToDeg),
      Num(e(5) * kRadToDeg),
      std::to_string(s.quality.points),
      Num(s.quality.own_cell_fraction),
      Num(s.quality.inlier_fraction),
      Num(s.quality.mean_score),
      Num(s.quality.median_distance),
      Num(s.constraints.constraint_ratio),
      Num(s.constraints.flatness),
      Num(s.constraints.probe_evidence),
      std::to_string(s.attempts),
      std::to_string(s.num_iterations),
      Num(o.time_ms),
      Num(r.times.total_ms),
      Num(r.times.map_ms),
      Num(r.times.sampling_ms),
      Num(r.times.solve_ms)};
  std::string line;
  for (size_t k = 0; k < fields.size(); ++k) {
    line += (k > 0 ? "," : "") + fields[k];
  }
  return line + "\n";
}

tools::Json ConfusionJson(const ConfusionTable& c) {
  tools::Json counts = tools::Json::object();
  for (const TerminationType type : c.types) {
    counts[TerminationTypeToString(type)] = {{"right", c.Count(true, type)},
                                             {"wrong", c.Count(false, type)}};
  }
  return {{"counts", counts},
          {"runs", c.total()},
          {"right", c.total_right()},
          {"success", tools::Number(c.Success())},
          {"precision", tools::Number(c.Precision())},
          {"recall", tools::Number(c.Recall())},
          {"usable_precision", tools::Number(c.UsablePrecision())},
          {"usable_recall", tools::Number(c.UsableRecall())}};
}

tools::Json StartsJson(const SuiteScore& score) {
  tools::Json rows = tools::Json::array();
  for (const SuiteStartRow& r : score.by_start) {
    rows.push_back({{"dataset", score.datasets.at(r.dataset)},
                    {"start", StartKindToString(r.kind)},
                    {"runs", r.runs},
                    {"right", r.right},
                    {"convergence", r.convergence},
                    {"wrong_convergence", r.wrong_convergence},
                    {"skipped_pairs", r.skipped_pairs}});
  }
  return rows;
}

tools::Json AccuracyJson(const SuiteScore& score) {
  tools::Json rows = tools::Json::array();
  for (const SuiteAccuracyRow& r : score.accuracy) {
    rows.push_back({{"dataset", score.datasets.at(r.dataset)},
                    {"start", StartKindToString(r.kind)},
                    {"right", r.right},
                    {"rms_translation_m", tools::Number(r.rms_translation_m)},
                    {"mean_along_track_m", tools::Number(r.mean_along_track_m)},
                    {"rms_rotation_deg", tools::Number(r.rms_rotation_deg)},
                    {"median_time_ms", tools::Number(r.median_time_ms)}});
  }
  return rows;
}

tools::Json ShareJson(const SuiteShare& share) {
  return {{"runs", share.runs}, {"right", share.right}};
}

tools::Json ReachJson(const SuiteScore& score) {
  tools::Json rows = tools::Json::array();
  for (const SuiteReachRow& r : score.reach) {
    const StartOffset& offset = score.offsets.at(size_t(r.offset_index));
    tools::Json per_dataset = tools::Json::object();
    for (size_t d = 0; d < r.per_dataset.size(); ++d) {
      per_dataset[score.datasets[d]] = ShareJson(r.per_dataset[d]);
    }
    rows.push_back({{"offset", offset.label},
                    {"family", offset.family},
                    {"datasets", per_dataset},
                    {"all", ShareJson(r.all)}});
  }
  // The label of the reach: "none" (-1), null (not measured) or an offset.
  const auto label = [&](int reach) -> tools::Json {
    if (reach < 0) return reach == -1 ? tools::Json("none") : tools::Json();
    return score.offsets.at(size_t(reach)).label;
  };
  tools::Json families = tools::Json::array();
  for (const SuiteFamilyReach& f : score.family_reach) {
    tools::Json per_dataset = tools::Json::object();
    for (size_t d = 0; d < f.per_dataset.size(); ++d) {
      per_dataset[score.datasets[d]] = label(f.per_dataset[d]);
    }
    families.push_back({{"family", f.family},
                        {"datasets", per_dataset},
                        {"all", label(f.all)}});
  }
  return {{"share", tools::Number(score.reach_share)},
          {"offsets", rows},
          {"families", families}};
}

// The sorted values of one measure of the right (or wrong) runs.
}  // namespace

std::string SuiteRunsCsvHeader() {
  return "dataset,pair,reference,input,step,start_kind,start,"
         "start_error_m,start_error_deg,uncertainty_m,uncertainty_deg,"
         "termination,message,right,translation_error_m,rotation_error_deg,"
         "along_track_error_m,error_tx_m,error_ty_m,error_tz_m,"
         "error_alpha_deg,error_beta_deg,error_gamma_deg,fit_points,"
         "own_cell_fraction,inlier_fraction,mean_score,median_distance,"
         "constraint_ratio,flatness,probe_evidence,attempts,iterations,"
         "registration_ms,total_ms,"
         "map_ms,sampling_ms,solve_ms";
}

bool WriteSuiteRunsCsv(const std::string& path,
                       const std::vector<LoadedSuiteDataset>& datasets,
                       const std::vector<std::vector<SuiteRunResult>>& results,
                       std::string* error) {
  std::ostringstream out;
  out << SuiteRunsCsvHeader() << "\n";
  for (size_t d = 0; d < datasets.size(); ++d) {
    for (size_t k = 0; k < results.at(d).size(); ++k) {
      out << CsvRow(datasets[d], datasets[d].runs.at(k), results[d][k]);
    }
  }
  return WriteFileAtomically(path, out.str(), error);
}

tools::Json SuiteSummaryJson(const SuiteScore& score,
                             const SuiteRunInfo& info) {
  tools::Json json = tools::ToolJson("mlndt_suite");
  json["method"] = info.method;
  json["time_ms"] = {{"total", tools::Number(info.wall_time_s * 1e3)}};
  json["datasets"] = score.datasets;
  json["confusion"] = ConfusionJson(score.confusion);
  json["by_start"] = StartsJson(score);
  json["accuracy"] = AccuracyJson(score);
  json["reach"] = ReachJson(score);
  json["missed_targets"] = info.missed_targets;
  return json;
}

bool WriteSuiteOutputs(const std::string& dir,
                       const std::vector<LoadedSuiteDataset>& loaded,
                       const std::vector<std::vector<SuiteRunResult>>& results,
                       const SuiteScore& score,
                       const SuiteRunInfo& info,
                       bool plot,
                       const std::string& gnuplot,
                       const QualityCheckOptions* quality_check,
                       std::string* error) {
  if (!WriteSuiteRunsCsv(dir + "/runs.csv", loaded, results, error) ||
      !tools::WriteJsonFile(
          dir + "/summary.json", SuiteSummaryJson(score, info), error)) {
    return false;
  }
  std::printf(
      "\nwritten: %s/runs.csv, %s/summary.json", dir.c_str(), dir.c_str());
  if (plot) {
    if (!WriteSuiteQualityPlot(gnuplot, dir, results, quality_check, error)) {
      return false;
    }
    std::printf(", %s/quality.png", dir.c_str());
  }
  std::printf("\n");
  return true;
}

}  // namespace lab
}  // namespace mlndt
