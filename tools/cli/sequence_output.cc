#include "tools/cli/sequence_output.h"

#include <map>

#include "lab/eval/trajectory_io.h"
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
  for (const PairResult& r : results)
    ++start_layers[r.registration.start_layer];
  Json layers = Json::object();
  for (const auto& [layer, count] : start_layers) {
    layers[std::to_string(layer)] = count;
  }
  VerdictCounts verdicts;
  Json unusable = Json::array();
  for (const PairResult& r : results) {
    verdicts.Add(r.registration.termination_type);
    if (!IsUsableTermination(r.registration.termination_type)) {
      unusable.push_back(
          {{"reference", r.reference},
           {"input", r.input},
           {"termination",
            TerminationTypeToString(r.registration.termination_type)}});
    }
  }
  o["terminations"] = VerdictCountsJson(verdicts);
  o["usable_pairs"] = verdicts.usable();
  o["unusable_pairs"] = verdicts.unusable();
  o["unusable_pair_list"] = unusable;
  o["unusable_estimate"] =
      "the pair's --init guess (pairs.csv estimate_source 'guess'), chained "
      "into trajectory_kitti.txt in place of a registration";
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
  if (!WriteSequencePairsCsv(out + "pairs.csv", store, results, error) ||
      !WriteSequenceTraceCsv(out + "trace.csv", results, error)) {
    return false;
  }
  const std::vector<Isometry3d> chained =
      ChainTrajectory(results, options.step, false);
  if (!WriteKittiPoses(out + "trajectory_kitti.txt", chained, error) ||
      !WriteTumTrajectory(
          out + "trajectory_tum.txt", chained, options.step, input, error)) {
    return false;
  }
  return !has_truth ||
         WriteKittiPoses(out + "gt_trajectory_kitti.txt",
                         ChainTrajectory(results, options.step, true),
                         error);
}

std::string UnusablePairsMessage(const SequenceOptions& options,
                                 const std::vector<PairResult>& results) {
  VerdictCounts verdicts;
  std::string pairs;
  for (const PairResult& r : results) {
    verdicts.Add(r.registration.termination_type);
    if (!IsUsableTermination(r.registration.termination_type) &&
        pairs.size() < 200) {
      pairs += (pairs.empty() ? "" : ", ") + std::to_string(r.reference) +
               "->" + std::to_string(r.input) + " " +
               TerminationTypeToString(r.registration.termination_type);
    }
  }
  if (verdicts.unusable() == 0) return "";
  return std::to_string(verdicts.unusable()) + " of " +
         std::to_string(verdicts.total()) + " pairs have no usable result (" +
         pairs + "): trajectory_kitti.txt chains their --init=" +
         InitSpecToString(options.init) +
         " guess instead (estimate_source 'guess' in pairs.csv)";
}

std::vector<std::string> SequenceOutputFiles(bool has_truth, bool plots) {
  std::vector<std::string> outputs = {"pairs.csv",
                                      "summary.json",
                                      "trace.csv",
                                      "trajectory_kitti.txt",
                                      "trajectory_tum.txt"};
  if (has_truth) outputs.push_back("gt_trajectory_kitti.txt");
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
