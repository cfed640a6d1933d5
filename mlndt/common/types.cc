#include "mlndt/common/types.h"

#include "mlndt/common/internal/enum_strings.h"

namespace mlndt {

const char* TerminationTypeToString(TerminationType type) {
  switch (type) {
    case TerminationType::CONVERGENCE:
      return "CONVERGENCE";
    case TerminationType::NO_CONVERGENCE:
      return "NO_CONVERGENCE";
    case TerminationType::FAILURE:
      return "FAILURE";
    case TerminationType::LOW_QUALITY:
      return "LOW_QUALITY";
    case TerminationType::DEGENERATE:
      return "DEGENERATE";
  }
  return "UNKNOWN";
}

bool StringToTerminationType(std::string value, TerminationType* result) {
  UpperCase(&value);
  MLNDT_STRING_TO_ENUM(CONVERGENCE, TerminationType);
  MLNDT_STRING_TO_ENUM(NO_CONVERGENCE, TerminationType);
  MLNDT_STRING_TO_ENUM(FAILURE, TerminationType);
  MLNDT_STRING_TO_ENUM(LOW_QUALITY, TerminationType);
  MLNDT_STRING_TO_ENUM(DEGENERATE, TerminationType);
  return false;
}

}  // namespace mlndt
