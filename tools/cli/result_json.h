#pragma once

// The JSON object of a result struct, made from its table (result_table.h):
// one key per field, named as the field, in the table's order, the value in
// the struct's own unit (the table's); nested results are objects, lists of
// them arrays of objects, vectors arrays, matrices arrays of rows. Numbers
// that are not finite are null (json_output.h).

#include <string>
#include <vector>

#include "mlndt/common/result_table.h"
#include "tools/cli/json_output.h"

namespace mlndt {
namespace tools {

// Every field of `object` (a struct of `table`) but those named in `skip`.
Json ResultJson(const ResultTable& table,
                const void* object,
                const std::vector<std::string>& skip = {});

template <typename S>
Json ResultJsonOf(const ResultTable& table,
                  const S& object,
                  const std::vector<std::string>& skip = {}) {
  return ResultJson(table, static_cast<const void*>(&object), skip);
}

}  // namespace tools
}  // namespace mlndt
