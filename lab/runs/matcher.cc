#include "lab/runs/matcher.h"

#include "mlndt/common/internal/check_option.h"
#include "mlndt/common/internal/enum_strings.h"

namespace mlndt {

const char* MethodToString(Method method) {
  switch (method) {
    case Method::MLNDT:
      return "MLNDT";
    case Method::NDT:
      return "NDT";
  }
  return "UNKNOWN";
}

bool StringToMethod(std::string value, Method* result) {
  UpperCase(&value);
  if (value == "ML-NDT" || value == "ML_NDT") value = "MLNDT";
  MLNDT_STRING_TO_ENUM(MLNDT, Method);
  MLNDT_STRING_TO_ENUM(NDT, Method);
  return false;
}

bool MatcherOptions::IsValid(std::string* error) const {
  MLNDT_OPTION_ENUM(method, MethodToString);
  return method == Method::NDT ? ndt.IsValid(error) : mlndt.IsValid(error);
}

bool MatcherGridOptions(const MatcherOptions& options,
                        const PointCloud& reference,
                        LayeredGridOptions* grid_options,
                        std::string* error) {
  if (options.method == Method::NDT) {
    return NdtGridOptions(options.ndt, reference, grid_options, error);
  }
  *grid_options = options.mlndt.grid;
  return true;
}

void RegisterWithMatcher(const MatcherOptions& options,
                         const LayeredGrid& reference_map,
                         const PointCloud& input,
                         const Isometry3d& initial_reference_from_input,
                         RegistrationSummary* summary) {
  if (options.method == Method::NDT) {
    RegisterNdt(options.ndt,
                reference_map,
                input,
                initial_reference_from_input,
                summary);
  } else {
    Register(options.mlndt,
             reference_map,
             input,
             initial_reference_from_input,
             summary);
  }
}

void RegisterWithMatcher(const MatcherOptions& options,
                         const PointCloud& reference,
                         const PointCloud& input,
                         const Isometry3d& initial_reference_from_input,
                         RegistrationSummary* summary) {
  if (options.method == Method::NDT) {
    RegisterNdt(
        options.ndt, reference, input, initial_reference_from_input, summary);
  } else {
    Register(
        options.mlndt, reference, input, initial_reference_from_input, summary);
  }
}

}  // namespace mlndt
