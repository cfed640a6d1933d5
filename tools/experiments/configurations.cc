#include "tools/experiments/configurations.h"

#include <functional>
#include <sstream>

#include "mlndt/registration/registration_options.h"

namespace mlndt {
namespace experiments {
namespace {

MatcherOptions MlndtOptions(const RegistrationOptions& options) {
  MatcherOptions matcher;
  matcher.method = Method::MLNDT;
  matcher.mlndt = options;
  matcher.mlndt.num_threads = 1;
  return matcher;
}

std::string Join(const std::vector<double>& values) {
  std::ostringstream out;
  for (size_t i = 0; i < values.size(); ++i) out << (i ? "," : "") << values[i];
  return values.empty() ? "(none)" : out.str();
}

template <typename T>
std::string Text(const T& value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

// The options the ablation steps through, read from RegistrationOptions.
using Getter = std::function<std::string(const RegistrationOptions&)>;
const std::vector<std::pair<std::string, Getter>>& ComparedOptions() {
  static const auto* const kOptions =
      new std::vector<std::pair<std::string, Getter>>{
          {"objective.loss",
           [](const RegistrationOptions& o) {
             return std::string(LossTypeToString(o.objective.loss));
           }},
          {"objective.loss_scale",
           [](const RegistrationOptions& o) {
             return Text(o.objective.loss_scale);
           }},
          {"objective.unmatched_policy",
           [](const RegistrationOptions& o) {
             return std::string(
                 UnmatchedPolicyToString(o.objective.unmatched_policy));
           }},
          {"schedule.start_layer",
           [](const RegistrationOptions& o) {
             return Text(o.schedule.start_layer);
           }},
          {"schedule.iterations_per_layer",
           [](const RegistrationOptions& o) {
             return Text(o.schedule.iterations_per_layer);
           }},
          {"schedule.max_final_iterations",
           [](const RegistrationOptions& o) {
             return Text(o.schedule.max_final_iterations);
           }},
          {"schedule.step_tolerance",
           [](const RegistrationOptions& o) {
             return Text(o.schedule.step_tolerance);
           }},
          {"schedule.coarse_step_tolerance",
           [](const RegistrationOptions& o) {
             return Text(o.schedule.coarse_step_tolerance);
           }},
          {"schedule.max_coarse_point_stride",
           [](const RegistrationOptions& o) {
             return Text(o.schedule.max_coarse_point_stride);
           }},
          {"grid.num_layers",
           [](const RegistrationOptions& o) {
             return Text(o.grid.num_layers);
           }},
          {"grid.finest_cell_size_m",
           [](const RegistrationOptions& o) {
             return Text(o.grid.finest_cell_size_m);
           }},
          {"grid.division_constant",
           [](const RegistrationOptions& o) {
             return Text(o.grid.division_constant);
           }},
          {"grid.min_points_per_cell",
           [](const RegistrationOptions& o) {
             return Text(o.grid.min_points_per_cell);
           }},
          {"grid.coarse_weighting",
           [](const RegistrationOptions& o) {
             return std::string(
                 CoarseWeightingToString(o.grid.coarse_weighting));
           }},
          {"sampling.gbs_cell_size_m",
           [](const RegistrationOptions& o) {
             return Text(o.sampling.gbs_cell_size_m);
           }},
          {"min_matched_fraction",
           [](const RegistrationOptions& o) {
             return Text(o.min_matched_fraction);
           }},
          {"backend.type",
           [](const RegistrationOptions& o) {
             return std::string(BackendTypeToString(o.backend.type));
           }},
          {"retry.yaw_seeds_deg",
           [](const RegistrationOptions& o) {
             return Join(o.retry.yaw_seeds_deg);
           }},
          {"sampling.method",
           [](const RegistrationOptions& o) {
             return std::string(SamplingMethodToString(o.sampling.method));
           }},
      };
  return *kOptions;
}

}  // namespace

Configuration PaperConfiguration() {
  return {"paper", "paper preset", MlndtOptions(PaperRegistrationOptions())};
}

Configuration DefaultConfiguration() {
  return {"defaults", "defaults", MlndtOptions(RegistrationOptions())};
}

std::vector<Configuration> AblationConfigurations() {
  const RegistrationOptions defaults;
  RegistrationOptions step = PaperRegistrationOptions();
  std::vector<Configuration> steps = {PaperConfiguration()};
  step.objective.loss = defaults.objective.loss;
  step.objective.loss_scale = defaults.objective.loss_scale;
  steps.push_back({"loss", "+Cauchy loss", MlndtOptions(step)});
  step.objective.unmatched_policy = defaults.objective.unmatched_policy;
  steps.push_back({"nearest", "+nearest-cell scoring", MlndtOptions(step)});
  step.schedule = defaults.schedule;
  steps.push_back({"schedule", "+our schedule", MlndtOptions(step)});
  steps.push_back(DefaultConfiguration());
  return steps;
}

Configuration NdtConfiguration() {
  MatcherOptions matcher;
  matcher.method = Method::NDT;
  matcher.ndt.num_threads = 1;
  return {"ndt", "NDT", matcher};
}

Configuration WithRandomSampling(const Configuration& c, double fraction) {
  Configuration out = c;
  SamplingOptions& sampling = out.options.method == Method::NDT
                                  ? out.options.ndt.sampling
                                  : out.options.mlndt.sampling;
  sampling.method = SamplingMethod::RANDOM;
  sampling.random_fraction = fraction;
  sampling.random_count = 0;
  std::ostringstream percent;
  percent << fraction * 100.0;
  out.key += "_random" + percent.str();
  out.label += ", random " + percent.str() + " %";
  return out;
}

std::vector<OptionDifference> PaperDefaultDifferences() {
  const std::vector<Configuration> steps = AblationConfigurations();
  std::vector<OptionDifference> differences;
  for (const auto& [name, get] : ComparedOptions()) {
    const std::string paper = get(steps.front().options.mlndt);
    const std::string defaults = get(steps.back().options.mlndt);
    if (paper == defaults) continue;
    std::string changed_in;
    for (size_t i = 1; i < steps.size(); ++i) {
      if (get(steps[i].options.mlndt) != get(steps[i - 1].options.mlndt)) {
        changed_in = steps[i].label;
        break;
      }
    }
    differences.push_back({name, paper, defaults, changed_in});
  }
  return differences;
}

}  // namespace experiments
}  // namespace mlndt
