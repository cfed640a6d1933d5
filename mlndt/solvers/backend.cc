#include "mlndt/solvers/backend.h"

#include "mlndt/common/enum_table.h"

namespace mlndt {

const EnumTable& BackendTypeTable() {
  static const EnumTable table(
      {
          {static_cast<int>(BackendType::CERES), "CERES"},
          {static_cast<int>(BackendType::NEWTON), "NEWTON"},
          {static_cast<int>(BackendType::LEVENBERG_MARQUARDT),
           "LEVENBERG_MARQUARDT"},
      },
      {{static_cast<int>(BackendType::LEVENBERG_MARQUARDT), "LM"}});
  return table;
}

const char* BackendTypeToString(BackendType type) {
  return EnumToString(BackendTypeTable(), type);
}

bool StringToBackendType(std::string value, BackendType* type) {
  return StringToEnum(BackendTypeTable(), std::move(value), type);
}

}  // namespace mlndt
