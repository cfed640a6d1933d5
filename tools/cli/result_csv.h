#pragma once

// The CSV of a list of results of one struct, made from its table
// (result_table.h), as result_json.h makes their JSON: a header of the
// flattened field names (a nested result's fields as "outer.inner", the
// JSON's path), one row per result, each value in the struct's own unit.
// Lists of nested results (a trace) have no column (JSON only); vectors,
// integer lists and matrices are one cell of space-separated numbers
// (matrices row-major); enums their names; bools true/false; numbers in
// full precision (%.17g), "nan"/"inf"/"-inf" where the JSON has null.

#include <string>
#include <vector>

#include "mlndt/common/result_table.h"

namespace mlndt {
namespace tools {

// The flattened names of `table`'s columns, nested tables expanded.
std::vector<std::string> ResultCsvColumns(const ResultTable& table);

// The cells of `object` (a struct of `table`) in ResultCsvColumns' order.
std::vector<std::string> ResultCsvCells(const ResultTable& table,
                                        const void* object);

// A column written before the table's: its name and one cell per object.
struct CsvColumn {
  std::string name;
  std::vector<std::string> cells;
};

// Header and one line per object, `leading` columns first.
std::string ResultCsv(const ResultTable& table,
                      const std::vector<const void*>& objects,
                      const std::vector<CsvColumn>& leading = {});

template <typename S>
std::string ResultCsvOf(const ResultTable& table,
                        const std::vector<S>& objects,
                        const std::vector<CsvColumn>& leading = {}) {
  std::vector<const void*> pointers;
  for (const S& object : objects) pointers.push_back(&object);
  return ResultCsv(table, pointers, leading);
}

}  // namespace tools
}  // namespace mlndt
