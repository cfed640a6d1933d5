#include "mlndt/common/result_table.h"

namespace mlndt {

const char* ResultTypeToString(ResultType type) {
  switch (type) {
    case ResultType::NUMBER:
      return "number";
    case ResultType::INTEGER:
      return "integer";
    case ResultType::BOOL:
      return "bool";
    case ResultType::STRING:
      return "string";
    case ResultType::ENUM:
      return "enum";
    case ResultType::INTEGER_LIST:
      return "[integer]";
    case ResultType::VECTOR:
      return "vector";
    case ResultType::MATRIX:
      return "matrix";
    case ResultType::STRUCT:
      return "object";
    case ResultType::STRUCT_LIST:
      return "[object]";
  }
  return "unknown";
}

const ResultField* ResultTable::Find(const std::string& name) const {
  for (const ResultField& field : fields_) {
    if (field.name == name) return &field;
  }
  return nullptr;
}

}  // namespace mlndt
