#pragma once

// The option flags shared by the tools, made from the library's option
// tables (mlndt/common/option_table.h): one flag per described field of
// RegistrationOptions (ML-NDT) and NdtOptions (--method=ndt), named as the
// field, with the field's default, and its unit, range and help in --help.
// The names: the field's, except
//   sampling.method -> --sampling, backend.type -> --backend,
//   quality_check.enabled -> --quality_check,
//   backend.newton.x -> --newton_x, backend.levenberg_marquardt.x -> --lm_x,
//   NdtOptions' own cell_size_m, outlier_ratio, neighbors, max_iterations,
//   max_step_norm -> --ndt_<name>;
// initial_uncertainty.* have none (--initial_uncertainty=t,r sets them).
// A flag both methods read (sampling, range filter, cells, quality check,
// --step_tolerance, --num_threads) is one flag.
// They are registered with gflags when this file is linked (a tool that
// calls MatcherOptionsFromFlags gets them, and shows them in --help).

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "mlndt/common/option_table.h"
#include "tools/cli/flag_utils.h"
#include "tools/cli/option_flags_store.h"

namespace mlndt {
namespace tools {

// One flag made from an option table.
struct OptionFlag {
  std::string name;
  std::string mlndt_path;  // In RegistrationOptions; "" if ML-NDT ignores it.
  std::string ndt_path;    // In NdtOptions; "" if NDT ignores it.
  const OptionField* field = nullptr;
};

// Every flag made from the option tables, in the tables' order.
const std::vector<OptionFlag>& OptionFlags();
// The flag named `name`, nullptr when no flag is made from the tables.
const OptionFlag* FlagOfName(const std::string& name);

// Whether --<name> is one of these flags (for TableFlags).
bool IsSharedFlag(const std::string& name);

// Sets the fields of *s (of `table`, the struct at `prefix` in
// RegistrationOptions, or in NdtOptions with `ndt`) from the flags given;
// false with *error "--flag=value: expected ...".
bool ApplyGivenFlags(const OptionTable& table,
                     const std::string& prefix,
                     bool ndt,
                     void* s,
                     std::string* error);

// The one rule between the map's two layer-count flags: false with *error
// when --num_layers is given while `finest_cell_size_m` (the map options'
// value after the flags) is > 0, which derives n and would ignore it.
bool CheckLayerCountFlags(double finest_cell_size_m, std::string* error);

// The values of flags made from the tables, for tools that read one
// directly.
int IntFlag(const std::string& name);
double DoubleFlag(const std::string& name);
uint64_t Uint64Flag(const std::string& name);

}  // namespace tools
}  // namespace mlndt
