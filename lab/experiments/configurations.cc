#include "lab/experiments/configurations.h"

#include <sstream>

#include "mlndt/common/option_table.h"
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

// The options the ablation steps through, by their path in
// RegistrationOptions; names, types and values come from the option tables.
const std::vector<std::string>& ComparedOptions() {
  static const auto* const kOptions = new std::vector<std::string>{
      "objective.loss",
      "objective.loss_scale",
      "objective.unmatched_policy",
      "schedule.start_layer",
      "schedule.iterations_per_layer",
      "schedule.max_final_iterations",
      "schedule.step_tolerance",
      "schedule.coarse_step_tolerance",
      "schedule.max_coarse_point_stride",
      "grid.num_layers",
      "grid.finest_cell_size_m",
      "grid.division_constant",
      "grid.min_points_per_cell",
      "grid.coarse_weighting",
      "sampling.gbs_cell_size_m",
      "min_matched_fraction",
      "backend.type",
      "retry.yaw_seeds_deg",
      "sampling.method",
  };
  return *kOptions;
}

// The value of the option at `path` for the report: enums by their C++
// name, an empty list as "(none)".
std::string Value(const std::string& path, const RegistrationOptions& o) {
  const void* owner = nullptr;
  const OptionField* field =
      RegistrationOptionsTable().FindPath(path, &o, &owner);
  if (field->type == OptionType::ENUM) {
    return field->enum_table->ToString(
        field->get_enum(field->locate(const_cast<void*>(owner))));
  }
  const std::string text = field->Format(owner);
  return text.empty() ? "(none)" : text;
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
  for (const std::string& name : ComparedOptions()) {
    const auto get = [&name](const RegistrationOptions& o) {
      return Value(name, o);
    };
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
