#pragma once

// One description per result: the name (= the C++ field's), unit, help and a
// getter of every field of a result struct, written once next to the
// struct. The read-only sibling of option_table.h. From the table come
//   - the tools' JSON object of the result (tools/cli/result_json.h);
//   - the Python module's read-only properties and todict()
//     (python/src/result_binding.h);
//   - the reference of the result's JSON in docs/json_schema.md
//     (mlndt_options --format=results).
// So a field added to a result struct and its table reaches every surface
// under one name, in the struct's own units (s, m, rad).
//
// A getter maps a pointer to the struct to a ResultValue; it may compute
// (IsSolutionUsable, a transform's matrix) instead of reading a member.

#include <cstdint>
#include <functional>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "mlndt/common/enum_table.h"
#include "mlndt/common/types.h"

namespace mlndt {

class ResultTable;

// An enum's value by its name in the enum's table ("CONVERGENCE").
struct EnumName {
  std::string name;
};
// A nested result struct and its table.
struct NestedResult {
  const ResultTable* table = nullptr;
  const void* object = nullptr;
};
// A list of nested result structs of one table (a trace).
struct NestedResults {
  const ResultTable* table = nullptr;
  std::vector<const void*> objects;
};

// The order of ResultType: value.index() == static_cast<int>(field.type).
using ResultValue = std::variant<double,
                                 int64_t,
                                 bool,
                                 std::string,
                                 EnumName,
                                 std::vector<int64_t>,
                                 Eigen::VectorXd,
                                 Eigen::MatrixXd,
                                 NestedResult,
                                 NestedResults>;

enum class ResultType {
  NUMBER,        // double; NaN and infinities allowed.
  INTEGER,       // int64_t (counts, indices, bytes).
  BOOL,          // bool
  STRING,        // std::string
  ENUM,          // EnumName
  INTEGER_LIST,  // std::vector<int64_t>
  VECTOR,        // Eigen::VectorXd
  MATRIX,        // Eigen::MatrixXd (rows x columns; may have 0 rows)
  STRUCT,        // NestedResult
  STRUCT_LIST,   // NestedResults
};

// "number", "integer", "bool", "string", "enum", "[integer]", "vector",
// "matrix", "object", "[object]" (for docs).
const char* ResultTypeToString(ResultType type);

struct ResultField {
  std::string name;  // The C++ field's name (or the accessor's).
  ResultType type = ResultType::NUMBER;
  std::string unit;  // "m", "s", "m, rad"; empty when unitless.
  std::string help;
  const EnumTable* enum_table = nullptr;  // ENUM.
  const ResultTable* nested = nullptr;    // STRUCT and STRUCT_LIST.
  std::function<ResultValue(const void*)> get;

  template <typename S>
  ResultValue Get(const S& s) const {
    return get(static_cast<const void*>(&s));
  }
};

class ResultTable {
 public:
  const std::string& struct_name() const { return struct_name_; }
  const std::vector<ResultField>& fields() const { return fields_; }
  const ResultField* Find(const std::string& name) const;

 private:
  template <typename S>
  friend class ResultTableBuilder;

  std::string struct_name_;
  std::vector<ResultField> fields_;
};

// Builds the table of struct S, one call per field in the header's order.
template <typename S>
class ResultTableBuilder {
 public:
  explicit ResultTableBuilder(std::string struct_name) {
    table_.struct_name_ = std::move(struct_name);
  }

  ResultTableBuilder& Number(const char* name,
                             double S::*m,
                             const char* unit,
                             const char* help) {
    return Add(name, ResultType::NUMBER, unit, help, [m](const S& s) {
      return ResultValue(s.*m);
    });
  }
  // Any integer member (int, int64_t, size_t).
  template <typename I>
  ResultTableBuilder& Integer(const char* name,
                              I S::*m,
                              const char* unit,
                              const char* help) {
    static_assert(std::is_integral_v<I>, "Integer: an integer member");
    return Add(name, ResultType::INTEGER, unit, help, [m](const S& s) {
      return ResultValue(static_cast<int64_t>(s.*m));
    });
  }
  ResultTableBuilder& Bool(const char* name, bool S::*m, const char* help) {
    return Add(name, ResultType::BOOL, "", help, [m](const S& s) {
      return ResultValue(s.*m);
    });
  }
  ResultTableBuilder& String(const char* name,
                             std::string S::*m,
                             const char* help) {
    return Add(name, ResultType::STRING, "", help, [m](const S& s) {
      return ResultValue(s.*m);
    });
  }
  template <typename E>
  ResultTableBuilder& Enum(const char* name,
                           E S::*m,
                           const EnumTable& table,
                           const char* help) {
    const EnumTable* t = &table;
    Add(name, ResultType::ENUM, "", help, [m, t](const S& s) {
      return ResultValue(EnumName{t->ToString(static_cast<int>(s.*m))});
    });
    table_.fields_.back().enum_table = &table;
    return *this;
  }
  template <typename I>
  ResultTableBuilder& IntegerList(const char* name,
                                  std::vector<I> S::*m,
                                  const char* help) {
    return Add(name, ResultType::INTEGER_LIST, "", help, [m](const S& s) {
      return ResultValue(std::vector<int64_t>((s.*m).begin(), (s.*m).end()));
    });
  }
  // A fixed-size Eigen vector member.
  template <typename V>
  ResultTableBuilder& Vector(const char* name,
                             V S::*m,
                             const char* unit,
                             const char* help) {
    return Add(name, ResultType::VECTOR, unit, help, [m](const S& s) {
      return ResultValue(Eigen::VectorXd(s.*m));
    });
  }
  // A fixed-size Eigen matrix member.
  template <typename M>
  ResultTableBuilder& Matrix(const char* name,
                             M S::*m,
                             const char* unit,
                             const char* help) {
    return Add(name, ResultType::MATRIX, unit, help, [m](const S& s) {
      return ResultValue(Eigen::MatrixXd(s.*m));
    });
  }
  // A list of fixed-size vectors as a matrix, one row each (k x n, k >= 0).
  template <typename V>
  ResultTableBuilder& Rows(const char* name,
                           std::vector<V> S::*m,
                           const char* unit,
                           const char* help) {
    return Add(name, ResultType::MATRIX, unit, help, [m](const S& s) {
      Eigen::MatrixXd rows(static_cast<Eigen::Index>((s.*m).size()),
                           V::RowsAtCompileTime);
      for (size_t i = 0; i < (s.*m).size(); ++i) {
        rows.row(static_cast<Eigen::Index>(i)) = (s.*m)[i].transpose();
      }
      return ResultValue(std::move(rows));
    });
  }
  template <typename N>
  ResultTableBuilder& Struct(const char* name,
                             N S::*m,
                             const ResultTable& table,
                             const char* help) {
    const ResultTable* t = &table;
    Add(name, ResultType::STRUCT, "", help, [m, t](const S& s) {
      return ResultValue(NestedResult{t, &(s.*m)});
    });
    table_.fields_.back().nested = &table;
    return *this;
  }
  template <typename N>
  ResultTableBuilder& StructList(const char* name,
                                 std::vector<N> S::*m,
                                 const ResultTable& table,
                                 const char* help) {
    const ResultTable* t = &table;
    Add(name, ResultType::STRUCT_LIST, "", help, [m, t](const S& s) {
      NestedResults list{t, {}};
      for (const N& n : s.*m) list.objects.push_back(&n);
      return ResultValue(std::move(list));
    });
    table_.fields_.back().nested = &table;
    return *this;
  }
  // A value computed from the struct (an accessor's, a transform's matrix);
  // `get` must return the alternative of `type`.
  ResultTableBuilder& Computed(const char* name,
                               ResultType type,
                               const char* unit,
                               const char* help,
                               std::function<ResultValue(const S&)> get) {
    return Add(name, type, unit, help, std::move(get));
  }

  ResultTable Build() { return std::move(table_); }

 private:
  ResultTableBuilder& Add(const char* name,
                          ResultType type,
                          const char* unit,
                          const char* help,
                          std::function<ResultValue(const S&)> get) {
    ResultField field;
    field.name = name;
    field.type = type;
    field.unit = unit;
    field.help = help;
    field.get = [get = std::move(get)](const void* s) {
      return get(*static_cast<const S*>(s));
    };
    table_.fields_.push_back(std::move(field));
    return *this;
  }

  ResultTable table_;
};

}  // namespace mlndt
