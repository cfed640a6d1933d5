#include "mlndt/solvers/backend.h"

#include "mlndt/common/internal/enum_strings.h"

namespace mlndt {

const char* BackendTypeToString(BackendType type) {
  switch (type) {
    case BackendType::CERES:
      return "CERES";
    case BackendType::NEWTON:
      return "NEWTON";
    case BackendType::LEVENBERG_MARQUARDT:
      return "LEVENBERG_MARQUARDT";
  }
  return "UNKNOWN";
}

bool StringToBackendType(std::string value, BackendType* result) {
  UpperCase(&value);
  if (value == "LM") value = "LEVENBERG_MARQUARDT";
  MLNDT_STRING_TO_ENUM(CERES, BackendType);
  MLNDT_STRING_TO_ENUM(NEWTON, BackendType);
  MLNDT_STRING_TO_ENUM(LEVENBERG_MARQUARDT, BackendType);
  return false;
}

}  // namespace mlndt
