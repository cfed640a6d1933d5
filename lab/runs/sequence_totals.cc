#include "lab/runs/sequence_totals.h"

#include <cmath>

#include "mlndt/common/pose.h"

namespace mlndt {

const char* const* ErrorNames() {
  static const char* const kNames[kNumErrorValues] = {"tx_cm",
                                                      "ty_cm",
                                                      "tz_cm",
                                                      "alpha_deg",
                                                      "beta_deg",
                                                      "gamma_deg",
                                                      "translation_cm",
                                                      "rotation_deg"};
  return kNames;
}

std::vector<double> ErrorValues(const PoseError& e) {
  std::vector<double> v(kNumErrorValues);
  for (int k = 0; k < 3; ++k) v[k] = std::abs(e.components(k)) * 100.0;
  for (int k = 3; k < 6; ++k) v[k] = std::abs(e.components(k)) * kRadToDeg;
  v[6] = e.translation_m * 100.0;
  v[7] = e.rotation_rad * kRadToDeg;
  return v;
}

SequenceTotals ComputeTotals(const std::vector<PairResult>& results) {
  SequenceTotals t;
  t.pairs = results.size();
  t.has_truth = !results.empty() && results.front().has_truth;
  std::vector<std::vector<double>> errors(kNumErrorValues);
  std::vector<std::vector<double>> errors_successful(kNumErrorValues);
  std::vector<double> time, map, registration, iterations;
  for (const PairResult& r : results) {
    t.registration_failures +=
        r.registration.termination_type == TerminationType::FAILURE;
    t.guess_check_failures += r.guess_check_failed;
    time.push_back(r.times.total_ms);
    map.push_back(r.times.map_ms);
    registration.push_back(r.times.total_ms - r.times.map_ms);
    iterations.push_back(r.registration.num_iterations);
    if (!r.has_truth) continue;
    t.successes += r.success;
    t.strict_successes += r.strict_success;
    const std::vector<double> v = ErrorValues(r.error);
    for (int k = 0; k < kNumErrorValues; ++k) {
      errors[k].push_back(v[k]);
      if (r.success) errors_successful[k].push_back(v[k]);
    }
  }
  if (t.pairs > 0 && t.has_truth) {
    t.success_rate_percent = 100.0 * t.successes / t.pairs;
    t.strict_success_rate_percent = 100.0 * t.strict_successes / t.pairs;
  }
  for (int k = 0; k < kNumErrorValues; ++k) {
    t.errors[k] = ComputeStats(errors[k]);
    t.errors_successful[k] = ComputeStats(errors_successful[k]);
  }
  t.time_ms = ComputeStats(time);
  t.map_time_ms = ComputeStats(map);
  t.registration_time_ms = ComputeStats(registration);
  t.iterations = ComputeStats(iterations);
  return t;
}

}  // namespace mlndt
