#include "tools/cli/sequence_output.h"

#include <cstdio>
#include <map>
#include <sstream>

#include "lab/eval/trajectory_io.h"
#include "lab/report/text_format.h"
#include "lab/runs/sequence_totals.h"
#include "mlndt/cloud/pose_io.h"
#include "mlndt/common/atomic_file.h"
#include "mlndt/common/pose.h"
#include "tools/cli/verdict_counts_json.h"

namespace mlndt {
namespace tools {
namespace {

Json ErrorsJson(const std::vector<Stats>& errors) {
  Json o;
  for (int k = 0; k < 8; ++k) o[ErrorNames()[k]] = StatsJson(errors[k]);
  return o;
}

// pairs.csv: one row per pair. Error columns (signed components of the
// error transform, norms, success flags) are empty without ground truth.
bool WritePairsCsv(const std::string& path,
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
         "deg,usable,estimate_source\n";
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
    // An unusable result keeps its --init guess as its estimate: say so.
    const bool usable = IsUsableTermination(r.termination);
    out << "," << int(usable) << "," << (usable ? "registration" : "guess")
        << "\n";
  }
  return WriteFileAtomically(path, out.str(), error);
}

// trace.csv: every iteration of every pair.
bool WriteTraceCsv(const std::string& path,
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

// The chained trajectory in TUM format, stamped with the scans' times.
bool WriteTumTrajectory(const std::string& path,
                        const std::vector<Isometry3d>& poses,
                        size_t step,
                        const ScanInput& input,
                        std::string* error) {
  Trajectory trajectory;
  for (size_t k = 0; k < poses.size(); ++k) {
    if (!trajectory.TryAdd(input.StampOf(k * step), poses[k], error)) {
      *error = path + ": scan " + input.name(k * step) + ": " + *error;
      return false;
    }
  }
  return WriteTrajectory(
      path, TrajectoryFormat::TUM, trajectory, input.TumComment(), error);
}

}  // namespace

Json SummaryJson(const Json& header, const std::vector<PairResult>& results) {
  const SequenceTotals t = ComputeTotals(results);
  Json o = header;
  o["pairs"] = t.pairs;
  o["has_ground_truth"] = t.has_truth;
  if (t.has_truth) {
    o["success_rule"] = "translation error < 50 cm (the paper, Section 5.2.1)";
    o["successes"] = t.successes;
    o["success_rate_percent"] = Number(t.success_rate_percent);
    o["strict_success_rule"] =
        "translation error < 20 cm and rotation error < 1 deg";
    o["strict_successes"] = t.strict_successes;
    o["strict_success_rate_percent"] = Number(t.strict_success_rate_percent);
    o["errors_note"] =
        "|component| of the error transform truth^-1 * estimate (cm, deg), "
        "std = sample standard deviation";
    o["errors"] = ErrorsJson(t.errors);
    o["errors_successful_pairs"] = ErrorsJson(t.errors_successful);
  } else {
    o["success_rate_percent"] = nullptr;
    o["strict_success_rate_percent"] = nullptr;
  }
  std::map<int, int> start_layers;
  for (const PairResult& r : results) ++start_layers[r.start_layer];
  Json layers = Json::object();
  for (const auto& [layer, count] : start_layers) {
    layers[std::to_string(layer)] = count;
  }
  VerdictCounts verdicts;
  Json unusable = Json::array();
  for (const PairResult& r : results) {
    verdicts.Add(r.termination);
    if (!IsUsableTermination(r.termination)) {
      unusable.push_back(
          {{"reference", r.reference},
           {"input", r.input},
           {"termination", TerminationTypeToString(r.termination)}});
    }
  }
  o["terminations"] = VerdictCountsJson(verdicts);
  o["usable_pairs"] = verdicts.usable();
  o["unusable_pairs"] = verdicts.unusable();
  o["unusable_pair_list"] = unusable;
  o["unusable_estimate"] =
      "the pair's --init guess (pairs.csv estimate_source 'guess'), chained "
      "into trajectory.txt in place of a registration";
  o["registration_failures"] = t.registration_failures;
  o["guess_check_failures"] = t.guess_check_failures;
  o["time_note"] = "per pair: pair = map + registration; p95 = nearest rank";
  o["time_ms_stats"] = {{"pair", StatsJson(t.time_ms)},
                        {"map", StatsJson(t.map_time_ms)},
                        {"registration", StatsJson(t.registration_time_ms)}};
  o["mean_iterations"] = Number(t.iterations.mean);
  o["start_layer_counts"] = layers;
  return o;
}

void PrintSequenceTotals(const SequenceOptions& options,
                         const std::vector<PairResult>& results,
                         const std::string& output_dir) {
  const SequenceTotals t = ComputeTotals(results);
  std::printf("pairs: %zu (step %zu, init %s, %s)\n",
              t.pairs,
              options.step,
              InitSpecToString(options.init).c_str(),
              MethodToString(options.registration.method));
  if (t.has_truth) {
    std::printf(
        "success (< 50 cm): %zu/%zu = %.1f %%, strict (< 20 cm, < 1 deg): "
        "%zu/%zu = %.1f %%\n",
        t.successes,
        t.pairs,
        t.success_rate_percent,
        t.strict_successes,
        t.pairs,
        t.strict_success_rate_percent);
    std::printf(
        "error |mean| (std, max): t %.2f cm (%.2f, %.2f), r %.3f deg (%.3f, "
        "%.3f)\n",
        t.errors[6].mean,
        t.errors[6].std,
        t.errors[6].max,
        t.errors[7].mean,
        t.errors[7].std,
        t.errors[7].max);
  }
  std::printf(
      "time per pair [ms]: mean %.1f, median %.1f, p95 %.1f, max %.1f (map "
      "mean %.1f); "
      "iterations mean %.1f\n",
      t.time_ms.mean,
      t.time_ms.median,
      t.time_ms.p95,
      t.time_ms.max,
      t.map_time_ms.mean,
      t.iterations.mean);
  VerdictCounts verdicts;
  for (const PairResult& r : results) verdicts.Add(r.termination);
  std::printf("verdicts: %s; usable %zu of %zu\n",
              verdicts.Line().c_str(),
              verdicts.usable(),
              verdicts.total());
  std::printf("output: %s\n", output_dir.c_str());
}

Json SequenceSummaryHeader(const SequenceOptions& options,
                           const SequenceSource& source,
                           size_t num_scans) {
  const MatcherOptions& registration = options.registration;
  Json header = ToolJson("mlndt_sequence");
  header["scans_dir"] = source.scans_dir;
  if (!source.bag.empty()) {
    header["bag"] = source.bag;
    header["topic"] = source.topic;
  }
  header["scans"] = num_scans;
  header["step"] = options.step;
  header["init"] = InitSpecToString(options.init);
  header["method"] = MethodToString(registration.method);
  header["backend"] = BackendTypeToString(registration.mlndt.backend.type);
  header["sampling"] = SamplingMethodToString(
      registration.method == Method::NDT ? registration.ndt.sampling.method
                                         : registration.mlndt.sampling.method);
  header["adaptive_start_layer"] = options.adaptive.enabled;
  if (options.adaptive.enabled) {
    Json thresholds = Json::array();
    for (const double v : options.adaptive.fail_rate_thresholds) {
      thresholds.push_back(Number(v));
    }
    header["adaptive"] = {
        {"max_translation_m", Number(options.adaptive.max_translation_m)},
        {"max_rotation_deg", Number(options.adaptive.max_rotation_deg)},
        {"fail_rate_thresholds", thresholds}};
  } else {
    header["start_layer_flag"] = source.start_layer_flag;
  }
  return header;
}

bool WriteSequenceFiles(const std::string& dir,
                        const SequenceOptions& options,
                        const ScanInput& input,
                        const ScanStore& store,
                        const std::vector<PairResult>& results,
                        bool has_truth,
                        std::string* error) {
  const std::string out = dir + "/";
  if (!WritePairsCsv(out + "pairs.csv", store, results, error) ||
      !WriteTraceCsv(out + "trace.csv", results, error)) {
    return false;
  }
  const std::vector<Isometry3d> chained =
      ChainTrajectory(results, options.step, false);
  if (!WriteKittiPoses(out + "trajectory.txt", chained, error) ||
      !WriteTumTrajectory(
          out + "trajectory_tum.txt", chained, options.step, input, error)) {
    return false;
  }
  return !has_truth ||
         WriteKittiPoses(out + "gt_trajectory.txt",
                         ChainTrajectory(results, options.step, true),
                         error);
}

std::string UnusablePairsMessage(const SequenceOptions& options,
                                 const std::vector<PairResult>& results) {
  VerdictCounts verdicts;
  std::string pairs;
  for (const PairResult& r : results) {
    verdicts.Add(r.termination);
    if (!IsUsableTermination(r.termination) && pairs.size() < 200) {
      pairs += (pairs.empty() ? "" : ", ") + std::to_string(r.reference) +
               "->" + std::to_string(r.input) + " " +
               TerminationTypeToString(r.termination);
    }
  }
  if (verdicts.unusable() == 0) return "";
  return std::to_string(verdicts.unusable()) + " of " +
         std::to_string(verdicts.total()) + " pairs have no usable result (" +
         pairs + "): trajectory.txt chains their --init=" +
         InitSpecToString(options.init) +
         " guess instead (estimate_source 'guess' in pairs.csv)";
}

std::vector<std::string> SequenceOutputFiles(bool has_truth, bool plots) {
  std::vector<std::string> outputs = {"pairs.csv",
                                      "summary.json",
                                      "trace.csv",
                                      "trajectory.txt",
                                      "trajectory_tum.txt"};
  if (has_truth) outputs.push_back("gt_trajectory.txt");
  if (plots) {
    outputs.insert(outputs.end(),
                   {"errors_translation.png",
                    "errors_rotation.png",
                    "trajectory_xy.png",
                    "score_vs_iteration.png"});
  }
  return outputs;
}

}  // namespace tools
}  // namespace mlndt
