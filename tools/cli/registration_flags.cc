#include "tools/cli/registration_flags.h"

#include <gflags/gflags.h>
#include <glog/logging.h>

#include <vector>

#include "tools/cli/flag_utils.h"
#include "tools/cli/list_flags.h"

DEFINE_string(preset,
              "default",
              "default (the library's options) | paper (the paper's: n = 4, "
              "start layer 2, 3 iterations a layer, plain sum over own cells, "
              "Newton); flags given explicitly override the preset");
DEFINE_string(method,
              "mlndt",
              "mlndt (layered map, Mahalanobis score) | ndt (conventional "
              "single-grid NDT, Gaussian score, Newton; the ML-NDT-only flags "
              "are refused)");
DEFINE_string(
    initial_uncertainty,
    "",
    "How far the initial guess may be off: translation_m,rotation_deg "
    "(e.g. 0.5,5); picks the start layer, and a guess is never made "
    "worse; empty = unknown (sets initial_uncertainty.*; ML-NDT only)");

namespace mlndt {
namespace tools {
namespace {

// "--<flag as given> <rest>".
std::string Named(const std::string& flag, const std::string& rest) {
  return GivenFlagName(flag) + " " + rest;
}

// A flag the chosen sampling does not read is refused, not ignored.
bool CheckSampling(const SamplingOptions& sampling, std::string* error) {
  const SamplingMethod method = sampling.method;
  std::string ignored;
  if (FlagGiven("gbs_cell_size_m") && method != SamplingMethod::GBS) {
    ignored = Named("gbs_cell_size_m", "applies to --sampling=gbs only");
  } else if (FlagGiven("random_fraction") && method != SamplingMethod::RANDOM) {
    ignored = "--random_fraction applies to --sampling=random only";
  } else if (FlagGiven("seed") && method != SamplingMethod::RANDOM &&
             method != SamplingMethod::GBS) {
    ignored = "--seed applies to --sampling=random or gbs only";
  }
  if (ignored.empty()) return true;
  *error = ignored + " (the sampling is " + SamplingMethodToString(method) +
           "; it would be ignored)";
  return false;
}

// The quality-check thresholds are refused with --quality_check=false,
// which ignores them.
bool CheckQualityCheck(const QualityCheckOptions& check, std::string* error) {
  if (check.enabled) return true;
  for (const char* flag : {"min_inlier_fraction",
                           "max_mean_score",
                           "inlier_gate",
                           "min_constraint_ratio"}) {
    if (FlagGiven(flag)) {
      *error = std::string("--") + flag +
               " is a quality-check threshold; it is ignored with "
               "--quality_check=false";
      return false;
    }
  }
  return true;
}

bool ParseInitialUncertainty(InitialGuessUncertainty* u, std::string* error) {
  if (FLAGS_initial_uncertainty.empty()) return true;
  std::vector<double> v;
  if (!ParseNumberList(FLAGS_initial_uncertainty, &v) || v.size() != 2) {
    *error = "--initial_uncertainty=" + FLAGS_initial_uncertainty +
             ": expected translation_m,rotation_deg";
    return false;
  }
  u->given = true;
  u->translation_m = v[0];
  u->rotation_deg = v[1];
  return true;
}

// Flags the options given would ignore.
bool CheckMlNdt(const RegistrationOptions& options, std::string* error) {
  if (FlagGiven("loss_scale") && options.objective.loss == LossType::NONE) {
    *error = "--loss_scale is ignored with --loss=none (no robust loss)";
    return false;
  }
  for (const OptionFlag& flag : OptionFlags()) {
    const std::string& path = flag.mlndt_path;
    const char* type = path.rfind("backend.ceres.", 0) == 0    ? "ceres"
                       : path.rfind("backend.newton.", 0) == 0 ? "newton"
                       : path.rfind("backend.levenberg_marquardt.", 0) == 0
                           ? "levenberg_marquardt"
                           : nullptr;
    BackendType wanted = BackendType::CERES;
    if (type == nullptr || !FlagGiven(flag.name) ||
        (StringToBackendType(type, &wanted) &&
         wanted == options.backend.type)) {
      continue;
    }
    *error = Named(flag.name, "applies to --backend=") + type +
             " only (the backend is " +
             BackendTypeToString(options.backend.type) +
             "; it would be ignored)";
    return false;
  }
  return CheckLayerCountFlags(options.grid.finest_cell_size_m, error) &&
         CheckSampling(options.sampling, error) &&
         CheckQualityCheck(options.quality_check, error);
}

bool ParseMlNdt(RegistrationOptions* options, std::string* error) {
  if (FLAGS_preset == "paper") {
    *options = PaperRegistrationOptions();
  } else if (FLAGS_preset != "default") {
    *error = "--preset=" + FLAGS_preset + ": expected default or paper";
    return false;
  }
  if (!ApplyGivenFlags(RegistrationOptionsTable(), "", false, options, error) ||
      !ParseInitialUncertainty(&options->initial_uncertainty, error) ||
      !CheckMlNdt(*options, error)) {
    return false;
  }
  return options->IsValid(error);
}

bool ParseNdt(NdtOptions* options, std::string* error) {
  if (!ApplyGivenFlags(NdtOptionsTable(), "", true, options, error)) {
    return false;
  }
  // NDT takes --step_tolerance's value, the ML-NDT default included (as it
  // always has).
  options->step_tolerance = DoubleFlag("step_tolerance");
  return CheckSampling(options->sampling, error) &&
         CheckQualityCheck(options->quality_check, error) &&
         options->IsValid(error);
}

}  // namespace

bool MatcherOptionsFromFlags(MatcherOptions* options, std::string* error) {
  if (!StringToMethod(FLAGS_method, &options->method)) {
    *error = "--method=" + FLAGS_method + ": expected mlndt or ndt";
    return false;
  }
  const bool ndt = options->method == Method::NDT;
  for (const OptionFlag& flag : OptionFlags()) {
    if ((ndt ? flag.ndt_path : flag.mlndt_path).empty() &&
        FlagGiven(flag.name)) {
      *error = Named(flag.name, "does not apply to --method=" + FLAGS_method);
      return false;
    }
  }
  for (const char* flag : {"preset", "initial_uncertainty"}) {
    if (ndt && FlagGiven(flag)) {
      *error = std::string("--") + flag + " does not apply to --method=ndt";
      return false;
    }
  }
  return ndt ? ParseNdt(&options->ndt, error)
             : ParseMlNdt(&options->mlndt, error);
}

bool RangeFilterOptionsFromFlags(RangeFilterOptions* filter,
                                 std::string* error) {
  if (!ApplyGivenFlags(
          RangeFilterOptionsTable(), "range_filter.", false, filter, error)) {
    return false;
  }
  if (filter->IsValid(error)) return true;
  for (const OptionField& field : RangeFilterOptionsTable().fields()) {
    if (error->find(field.name) != std::string::npos) {
      *error = GivenFlagName(field.name) + ": " + *error;
      break;
    }
  }
  return false;
}

bool RegistrationOptionsFromFlags(RegistrationOptions* options,
                                  std::string* error) {
  return RegistrationOptionsFromFlags(RegistrationOptions(), options, error);
}

bool RegistrationOptionsFromFlags(const RegistrationOptions& defaults,
                                  RegistrationOptions* options,
                                  std::string* error) {
  MatcherOptions matcher;
  matcher.mlndt = defaults;
  if (!MatcherOptionsFromFlags(&matcher, error)) return false;
  if (matcher.method != Method::MLNDT) {
    *error = "--method=" + FLAGS_method + ": this tool runs ML-NDT only";
    return false;
  }
  *options = matcher.mlndt;
  return true;
}

void ShowRegistrationDefaults(const RegistrationOptions& defaults) {
  const RegistrationOptions library;
  for (const OptionFlag& flag : OptionFlags()) {
    if (flag.mlndt_path.empty()) continue;
    const void* owner = nullptr;
    const void* library_owner = nullptr;
    const OptionField* field =
        RegistrationOptionsTable().FindPath(flag.mlndt_path, &defaults, &owner);
    RegistrationOptionsTable().FindPath(
        flag.mlndt_path, &library, &library_owner);
    if (field == nullptr) continue;
    const std::string value = field->Format(owner);
    if (value == field->Format(library_owner)) continue;
    CHECK(!gflags::SetCommandLineOptionWithMode(
               flag.name.c_str(), value.c_str(), gflags::SET_FLAGS_DEFAULT)
               .empty())
        << "--" << flag.name << "=" << value;
  }
}

}  // namespace tools
}  // namespace mlndt
