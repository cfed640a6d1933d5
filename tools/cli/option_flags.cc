#include "tools/cli/option_flags.h"

#include <gflags/gflags.h>

#include <deque>
#include <map>
#include <set>

#include "mlndt/ndt/ndt_registration.h"
#include "mlndt/registration/registration_options.h"
#include "tools/cli/flag_utils.h"
#include "tools/cli/tool_main.h"

namespace mlndt {
namespace tools {
namespace {

// The naming rules below are function-local statics: OptionFlags() may be
// first called while another file's flags are registered at
// static-initialisation time (table_flags.h), before this file's statics.
// Fields whose flag is not their name.
const std::map<std::string, std::string>& Renamed() {
  static const std::map<std::string, std::string> renamed = {
      {"sampling.method", "sampling"},
      {"backend.type", "backend"},
      {"quality_check.enabled", "quality_check"}};
  return renamed;
}
// Nested structs whose fields' flags get a prefix.
const std::vector<std::pair<std::string, std::string>>& Prefixes() {
  static const std::vector<std::pair<std::string, std::string>> prefixes = {
      {"backend.newton.", "newton_"},
      {"newton.", "newton_"},
      {"backend.levenberg_marquardt.", "lm_"}};
  return prefixes;
}
// NdtOptions' own fields: their flags are --ndt_<name>.
const std::set<std::string>& NdtOwn() {
  static const std::set<std::string> own = {"cell_size_m",
                                            "outlier_ratio",
                                            "neighbors",
                                            "max_iterations",
                                            "max_step_norm"};
  return own;
}
// Structs without flags.
const std::set<std::string>& NoFlags() {
  static const std::set<std::string> none = {"initial_uncertainty"};
  return none;
}

std::string FlagName(const std::string& path, bool ndt) {
  const auto renamed = Renamed().find(path);
  if (renamed != Renamed().end()) return renamed->second;
  if (ndt && NdtOwn().count(path) > 0) return "ndt_" + path;
  const std::string leaf = path.substr(path.rfind('.') + 1);
  for (const auto& [prefix, flag_prefix] : Prefixes()) {
    if (path.rfind(prefix, 0) == 0) return flag_prefix + leaf;
  }
  return leaf;
}

void Collect(const OptionTable& table,
             const std::string& prefix,
             bool ndt,
             std::vector<OptionFlag>* flags) {
  for (const OptionField& field : table.fields()) {
    const std::string path = prefix + field.name;
    if (field.type == OptionType::STRUCT) {
      if (NoFlags().count(path) == 0) {
        Collect(*field.nested, path + ".", ndt, flags);
      }
      continue;
    }
    const std::string name = FlagName(path, ndt);
    OptionFlag* flag = nullptr;
    for (OptionFlag& f : *flags) {
      if (f.name == name) flag = &f;
    }
    if (flag == nullptr) {
      flags->push_back({name, "", "", &field});
      flag = &flags->back();
    }
    (ndt ? flag->ndt_path : flag->mlndt_path) = path;
  }
}

// The field's default: RegistrationOptions()' (NdtOptions()' for a flag of
// conventional NDT only).
std::string DefaultText(const OptionFlag& flag) {
  const bool ndt = flag.mlndt_path.empty();
  const OptionTable& table =
      ndt ? NdtOptionsTable() : RegistrationOptionsTable();
  const void* owner = nullptr;
  const OptionField* field = table.FindPath(
      ndt ? flag.ndt_path : flag.mlndt_path, table.defaults(), &owner);
  return field->Format(owner);
}

std::string HelpText(const OptionFlag& flag) {
  std::string help = flag.field->FullHelp();
  if (flag.ndt_path.empty()) return help + " (ML-NDT only)";
  if (flag.mlndt_path.empty()) return "--method=ndt: " + help;
  return help;
}

// The flag's option path for --help's headings (tool_main.h): ML-NDT's,
// or "ndt:" and NDT's for a flag of conventional NDT only.
std::string OptionPathOf(const std::string& name) {
  for (const OptionFlag& flag : OptionFlags()) {
    if (flag.name != name) continue;
    return flag.mlndt_path.empty() ? "ndt:" + flag.ndt_path : flag.mlndt_path;
  }
  return "";
}

// Registers the shared flags with gflags at static-initialisation time
// (what the DEFINE_ macros do).
class FlagRegistry {
 public:
  FlagRegistry() {
    SetOptionPathOfFlag(&OptionPathOf);
    for (const OptionFlag& flag : OptionFlags()) {
      RegisterOptionFlag(flag.name,
                         HelpText(flag),
                         __FILE__,
                         flag.field->type,
                         DefaultText(flag));
    }
  }
};

const FlagRegistry kRegistry;

}  // namespace

bool IsSharedFlag(const std::string& name) {
  return FlagOfName(name) != nullptr;
}

const std::vector<OptionFlag>& OptionFlags() {
  static const std::vector<OptionFlag> flags = [] {
    std::vector<OptionFlag> f;
    Collect(RegistrationOptionsTable(), "", false, &f);
    Collect(NdtOptionsTable(), "", true, &f);
    return f;
  }();
  return flags;
}

const OptionFlag* FlagOfName(const std::string& name) {
  for (const OptionFlag& flag : OptionFlags()) {
    if (flag.name == name) return &flag;
  }
  return nullptr;
}

bool ApplyGivenFlags(const OptionTable& table,
                     const std::string& prefix,
                     bool ndt,
                     void* s,
                     std::string* error) {
  for (const OptionFlag& flag : OptionFlags()) {
    const std::string& path = ndt ? flag.ndt_path : flag.mlndt_path;
    if (path.empty() || path.rfind(prefix, 0) != 0 || !FlagGiven(flag.name)) {
      continue;
    }
    const void* owner = nullptr;
    const OptionField* field =
        table.FindPath(path.substr(prefix.size()), s, &owner);
    if (field == nullptr) continue;
    const std::string text = FlagText(flag.name);
    if (!field->Parse(text, const_cast<void*>(owner), error)) {
      *error = GivenFlagName(flag.name) + "=" + text + ": " + *error;
      return false;
    }
  }
  return true;
}

bool CheckLayerCountFlags(double finest_cell_size_m, std::string* error) {
  if (!FlagGiven("num_layers") || finest_cell_size_m <= 0.0) return true;
  const std::string finest = GivenFlagName("finest_cell_size_m");
  *error = "--num_layers is ignored while " + finest +
           " > 0 (n is derived from it): give " + finest +
           "=0 with --num_layers";
  return false;
}

int IntFlag(const std::string& name) { return std::stoi(FlagText(name)); }
double DoubleFlag(const std::string& name) { return std::stod(FlagText(name)); }
uint64_t Uint64Flag(const std::string& name) {
  return std::stoull(FlagText(name));
}

}  // namespace tools
}  // namespace mlndt
