#pragma once

// One description per option: the name (= the C++ field's), unit, valid
// range and help text of every field of an options struct, written once next
// to the struct's IsValid. The default is the struct's default constructor's
// (never repeated); enum fields carry their EnumTable. From the table come
//   - IsValid's range checks and messages ("invalid option: x = v; it must
//     be in [lo, hi]"), see CheckRanges;
//   - the tools' flags and --help (tools/cli/registration_flags.cc);
//   - the Python keywords and docstrings (python/src/options.cc);
//   - the option reference docs/options.md (mlndt_options_doc).
// The type-erased fields are read and written through `locate`, which maps a
// pointer to the struct to a pointer to the field.

#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "mlndt/common/enum_table.h"

namespace mlndt {

enum class OptionType { BOOL, INT, UINT64, DOUBLE, DOUBLE_LIST, ENUM, STRUCT };

// The valid values of a number (of each element of a list): lo <= x <= hi,
// either end open or infinite; `or_zero`: 0 is valid too (0 = off).
struct OptionRange {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;
  bool hi_open = false;
  bool or_zero = false;

  bool Contains(double x) const;  // False for NaN.
  // "in [0.001, 1000]", "in (0, 1]", ">= 1", "in [0.001, 100000] or 0".
  std::string ToString() const;
};

OptionRange Closed(double lo, double hi);        // [lo, hi]
OptionRange LeftOpen(double lo, double hi);      // (lo, hi]
OptionRange RightOpen(double lo, double hi);     // [lo, hi)
OptionRange AtLeast(double lo);                  // [lo, inf)
OptionRange ClosedOrZero(double lo, double hi);  // [lo, hi] or 0

class OptionTable;

struct OptionField {
  std::string name;  // The C++ field's name.
  OptionType type = OptionType::DOUBLE;
  std::string unit;  // "m", "deg", "m^2"; empty when unitless.
  std::string help;
  bool has_range = false;
  OptionRange range;                      // Numbers and list elements.
  const EnumTable* enum_table = nullptr;  // ENUM.
  const OptionTable* nested = nullptr;    // STRUCT.
  std::function<void*(void*)> locate;     // Struct -> field.
  int (*get_enum)(const void* field) = nullptr;
  void (*set_enum)(void* field, int value) = nullptr;

  template <typename T>
  T& Ref(void* s) const {
    return *static_cast<T*>(locate(s));
  }
  template <typename T>
  const T& Ref(const void* s) const {
    return *static_cast<const T*>(locate(const_cast<void*>(s)));
  }

  // The value as text that Parse reads back: true/false, numbers to full
  // precision, enums in lower case, lists comma-separated. Not for STRUCT.
  std::string Format(const void* s) const;
  // Sets the field from `text`; false with *error "expected ..." (the range
  // is CheckRange's).
  bool Parse(const std::string& text, void* s, std::string* error) const;
  // False with *error "invalid option: <prefix><name> = v; it must be ...".
  bool CheckRange(const void* s,
                  const std::string& prefix,
                  std::string* error) const;
  // "[m] In [0, 1000]." / "One of: none | huber | cauchy." (for help texts).
  std::string RangeText() const;
  // help + unit + range, one line.
  std::string FullHelp() const;
};

class OptionTable {
 public:
  const std::string& struct_name() const { return struct_name_; }
  const std::vector<OptionField>& fields() const { return fields_; }
  const OptionField* Find(const std::string& name) const;
  // The field at a dotted path ("grid.regularization.min_eigenvalue_m2"),
  // nullptr when there is none; *owner (when given) is the struct inside
  // `s` that holds it, for the field's Format, Parse and CheckRange.
  const OptionField* FindPath(const std::string& path,
                              const void* s = nullptr,
                              const void** owner = nullptr) const;
  // An instance built by the struct's default constructor.
  const void* defaults() const { return defaults_.get(); }
  // The struct's IsValid (nullptr for a plain-data struct without one).
  const std::function<bool(const void*, std::string*)>& is_valid() const {
    return is_valid_;
  }

  // Every field's range and enum value, and those of nested structs without
  // an IsValid of their own (prefixed "regularization."); nested structs
  // with one are left to it.
  bool CheckRanges(const void* s, std::string* error) const;
  template <typename S>
  bool Check(const S& s, std::string* error) const {
    return CheckRanges(static_cast<const void*>(&s), error);
  }

 private:
  template <typename S>
  friend class OptionTableBuilder;

  bool CheckRangesWithPrefix(const void* s,
                             const std::string& prefix,
                             std::string* error) const;

  std::string struct_name_;
  std::vector<OptionField> fields_;
  std::shared_ptr<const void> defaults_;
  std::function<bool(const void*, std::string*)> is_valid_;
};

// Builds the table of struct S, one call per field in the header's order.
template <typename S>
class OptionTableBuilder {
 public:
  explicit OptionTableBuilder(std::string struct_name) {
    table_.struct_name_ = std::move(struct_name);
    table_.defaults_ = std::make_shared<const S>();
  }

  OptionTableBuilder& Bool(const char* name, bool S::*m, const char* help) {
    return Add(MakeField(name, OptionType::BOOL, "", help, m));
  }
  OptionTableBuilder& Int(const char* name,
                          int S::*m,
                          OptionRange range,
                          const char* help) {
    return Add(Ranged(MakeField(name, OptionType::INT, "", help, m), range));
  }
  OptionTableBuilder& Uint64(const char* name,
                             uint64_t S::*m,
                             const char* help) {
    return Add(MakeField(name, OptionType::UINT64, "", help, m));
  }
  OptionTableBuilder& Uint64(const char* name,
                             uint64_t S::*m,
                             OptionRange range,
                             const char* help) {
    return Add(Ranged(MakeField(name, OptionType::UINT64, "", help, m), range));
  }
  OptionTableBuilder& Double(const char* name,
                             double S::*m,
                             const char* unit,
                             OptionRange range,
                             const char* help) {
    return Add(
        Ranged(MakeField(name, OptionType::DOUBLE, unit, help, m), range));
  }
  OptionTableBuilder& DoubleList(const char* name,
                                 std::vector<double> S::*m,
                                 const char* unit,
                                 OptionRange element_range,
                                 const char* help) {
    return Add(Ranged(MakeField(name, OptionType::DOUBLE_LIST, unit, help, m),
                      element_range));
  }
  template <typename E>
  OptionTableBuilder& Enum(const char* name,
                           E S::*m,
                           const EnumTable& table,
                           const char* help) {
    OptionField field = MakeField(name, OptionType::ENUM, "", help, m);
    field.enum_table = &table;
    // Through the underlying integer: a field may hold a value that is not
    // an enumerator (IsValid must reject it), and loading that as E is
    // undefined behaviour.
    field.get_enum = [](const void* p) {
      std::underlying_type_t<E> raw;
      std::memcpy(&raw, p, sizeof(raw));
      return static_cast<int>(raw);
    };
    field.set_enum = [](void* p, int v) {
      const auto raw = static_cast<std::underlying_type_t<E>>(v);
      std::memcpy(p, &raw, sizeof(raw));
    };
    return Add(std::move(field));
  }
  template <typename N>
  OptionTableBuilder& Struct(const char* name,
                             N S::*m,
                             const OptionTable& table,
                             const char* help) {
    OptionField field = MakeField(name, OptionType::STRUCT, "", help, m);
    field.nested = &table;
    return Add(std::move(field));
  }
  // The struct's IsValid, for callers that walk the table (Python).
  OptionTableBuilder& Validator(bool (S::*is_valid)(std::string*) const) {
    table_.is_valid_ = [is_valid](const void* s, std::string* error) {
      return (static_cast<const S*>(s)->*is_valid)(error);
    };
    return *this;
  }

  OptionTable Build() { return std::move(table_); }

 private:
  template <typename T>
  static OptionField MakeField(const char* name,
                               OptionType type,
                               const char* unit,
                               const char* help,
                               T S::*m) {
    OptionField field;
    field.name = name;
    field.type = type;
    field.unit = unit;
    field.help = help;
    field.locate = [m](void* s) -> void* { return &(static_cast<S*>(s)->*m); };
    return field;
  }
  static OptionField Ranged(OptionField field, OptionRange range) {
    field.has_range = true;
    field.range = range;
    return field;
  }
  OptionTableBuilder& Add(OptionField field) {
    table_.fields_.push_back(std::move(field));
    return *this;
  }

  OptionTable table_;
};

}  // namespace mlndt
