#include "mlndt/common/types.h"

#include "mlndt/common/enum_table.h"

namespace mlndt {

const EnumTable& TerminationTypeTable() {
  static const EnumTable table({
      {static_cast<int>(TerminationType::CONVERGENCE), "CONVERGENCE"},
      {static_cast<int>(TerminationType::NO_CONVERGENCE), "NO_CONVERGENCE"},
      {static_cast<int>(TerminationType::FAILURE), "FAILURE"},
      {static_cast<int>(TerminationType::LOW_QUALITY), "LOW_QUALITY"},
      {static_cast<int>(TerminationType::DEGENERATE), "DEGENERATE"},
  });
  return table;
}

const char* TerminationTypeToString(TerminationType type) {
  return EnumToString(TerminationTypeTable(), type);
}

bool StringToTerminationType(std::string value, TerminationType* type) {
  return StringToEnum(TerminationTypeTable(), std::move(value), type);
}

}  // namespace mlndt
