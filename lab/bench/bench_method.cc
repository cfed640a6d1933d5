#include "lab/bench/bench_method.h"

#include <cmath>
#include <cstdio>

#include "mlndt/registration/registration.h"

namespace mlndt {

bool BenchMethod::Prepare(const std::vector<ScanPair>& /*pairs*/,
                          std::string* /*error*/) {
  return true;
}

MlndtBenchMethod::MlndtBenchMethod(const BenchConfiguration& configuration,
                                   uint64_t seed)
    : configuration_(configuration), options_(configuration.Options(seed)) {}

BenchMethodLabels MlndtBenchMethod::Labels() const {
  return ConfigurationLabels(configuration_);
}

BenchEstimate MlndtBenchMethod::Run(size_t /*pair_index*/,
                                    const ScanPair& pair) {
  RegistrationSummary summary;
  Register(options_,
           *pair.reference,
           *pair.input,
           pair.initial_reference_from_input,
           &summary);
  BenchEstimate e;
  e.reference_from_input = summary.reference_from_input;
  e.usable = summary.IsSolutionUsable();
  e.converged = summary.termination_type == TerminationType::CONVERGENCE;
  e.covariance = summary.covariance;
  e.time_ms = summary.total_time_s * 1e3;
  e.iterations = summary.num_iterations;
  e.point_iterations = summary.point_iterations;
  e.score = summary.final_score;
  return e;
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
    labels.loss += "@" + BenchFormat("%g", c.Options(0).objective.loss_scale);
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

}  // namespace mlndt
