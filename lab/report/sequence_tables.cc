#include "lab/report/sequence_tables.h"

#include <cstdio>
#include <sstream>

#include "lab/eval/verdict_counts.h"
#include "lab/report/text_format.h"
#include "lab/runs/sequence_totals.h"
#include "mlndt/common/atomic_file.h"
#include "mlndt/common/pose.h"

namespace mlndt {

bool WriteSequencePairsCsv(const std::string& path,
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
    out << TerminationTypeToString(r.registration.termination_type) << ","
        << r.registration.num_iterations << "," << r.registration.start_layer
        << "," << r.registration.num_layers << ","
        << r.registration.sampled_points << "," << Num(r.times.total_ms) << ","
        << Num(r.times.map_ms) << "," << Num(r.times.sampling_ms) << ","
        << Num(r.times.solve_ms) << "," << Num(r.guess_deviation_m) << ","
        << Num(r.guess_deviation_deg) << "," << int(r.guess_check_failed) << ","
        << Num(r.running_fail_rate);
    const Vector6d xi = IsometryToPoseVector(r.estimate);
    for (int k = 0; k < 6; ++k)
      out << "," << Num(k < 3 ? xi(k) : xi(k) * kRadToDeg);
    // An unusable result keeps its --init guess as its estimate: say so.
    const bool usable = IsUsableTermination(r.registration.termination_type);
    out << "," << int(usable) << "," << (usable ? "registration" : "guess")
        << "\n";
  }
  return WriteFileAtomically(path, out.str(), error);
}

bool WriteSequenceTraceCsv(const std::string& path,
                           const std::vector<PairResult>& results,
                           std::string* error) {
  std::ostringstream out;
  out << "reference,input,iteration,layer,score,step_norm,step_is_successful,"
         "tx_m,ty_m,tz_m,alpha_deg,beta_deg,gamma_deg,time_ms\n";
  for (const PairResult& r : results) {
    for (const IterationRecord& it : r.registration.trace) {
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
  for (const PairResult& r : results)
    verdicts.Add(r.registration.termination_type);
  std::printf("verdicts: %s; usable %zu of %zu\n",
              verdicts.Line().c_str(),
              verdicts.usable(),
              verdicts.total());
  std::printf("output: %s\n", output_dir.c_str());
}

}  // namespace mlndt
