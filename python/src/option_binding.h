#pragma once

// The bridge between the library's option tables (mlndt/common/
// option_table.h: every field's name, unit, range and help, written once)
// and Python keyword arguments. A StructBinding walks a struct's table and
// gives
//   - Update: set the fields named in a dict, strictly typed; an unknown key
//     or a value of the wrong type raises ValueError naming the full path
//     ("grid.finest_cell_size_m");
//   - ToDict: every field, nested structs as dicts, enums as their XToString
//     names (what mlndt.default_options() returns);
//   - Validate: the struct's own IsValid (children first), with the path put
//     into the library's message;
//   - Describe: the field list with types, defaults, units and ranges, for
//     docstrings.
// A field added to a struct's table is a keyword here with no change.

#include <pybind11/pybind11.h>

#include <limits>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "mlndt/common/option_table.h"

namespace mlndt {
namespace python {

namespace py = pybind11;

// Raises ValueError(message).
[[noreturn]] void ThrowValueError(const std::string& message);

// A short description of a Python value for error messages: "'abc' (str)".
std::string DescribeValue(py::handle value);

// Python-side type tests that keep bool apart from int and str from numbers.
bool IsBoolLike(py::handle value);     // bool, numpy.bool_.
bool IsIntegerLike(py::handle value);  // int, numpy integers; not bool.
bool IsRealLike(py::handle value);     // numbers.Real but not bool.

// How a field's C++ type reads from and writes to Python.
template <typename T, typename Enable = void>
struct OptionCodec;

template <>
struct OptionCodec<bool> {
  static const char* TypeName() { return "bool"; }
  static bool FromPython(py::handle value, bool* out) {
    if (!IsBoolLike(value)) return false;
    *out = py::cast<bool>(py::bool_(py::reinterpret_borrow<py::object>(value)));
    return true;
  }
  static py::object ToPython(bool value) { return py::bool_(value); }
  static std::string Repr(bool value) { return value ? "True" : "False"; }
};

template <typename T>
struct OptionCodec<
    T,
    std::enable_if_t<std::is_integral_v<T> && !std::is_same_v<T, bool>>> {
  static const char* TypeName() { return "int"; }
  static bool FromPython(py::handle value, T* out) {
    if (!IsIntegerLike(value)) return false;
    // Through Python's int, so that numpy integers and big ints compare
    // exactly against the C++ type's range.
    const py::int_ as_int(py::reinterpret_borrow<py::object>(value));
    const py::int_ lo(std::numeric_limits<T>::min());
    const py::int_ hi(std::numeric_limits<T>::max());
    if (as_int < lo || as_int > hi) return false;
    *out = py::cast<T>(as_int);
    return true;
  }
  static py::object ToPython(T value) { return py::int_(value); }
  static std::string Repr(T value) { return std::to_string(value); }
};

template <>
struct OptionCodec<double> {
  static const char* TypeName() { return "float"; }
  static bool FromPython(py::handle value, double* out) {
    if (!IsRealLike(value)) return false;
    *out =
        py::cast<double>(py::float_(py::reinterpret_borrow<py::object>(value)));
    return true;
  }
  static py::object ToPython(double value) { return py::float_(value); }
  static std::string Repr(double value) {
    return py::str(py::float_(value)).cast<std::string>();
  }
};

template <>
struct OptionCodec<std::vector<double>> {
  static const char* TypeName() { return "list[float]"; }
  static bool FromPython(py::handle value, std::vector<double>* out) {
    if (py::isinstance<py::str>(value) || py::isinstance<py::bytes>(value) ||
        py::isinstance<py::dict>(value) || !py::hasattr(value, "__iter__")) {
      return false;
    }
    std::vector<double> values;
    for (py::handle item : py::reinterpret_borrow<py::iterable>(value)) {
      double v = 0.0;
      if (!OptionCodec<double>::FromPython(item, &v)) return false;
      values.push_back(v);
    }
    *out = std::move(values);
    return true;
  }
  static py::object ToPython(const std::vector<double>& value) {
    py::list list;
    for (const double v : value) list.append(py::float_(v));
    return std::move(list);
  }
  static std::string Repr(const std::vector<double>& value) {
    std::string out = "[";
    for (size_t i = 0; i < value.size(); ++i) {
      out += (i ? ", " : "") + OptionCodec<double>::Repr(value[i]);
    }
    return out + "]";
  }
};

// The Python side of an option table (non-template; StructBinding is its
// typed front). `s` points to a struct of the table's type.
void UpdateFromPython(const OptionTable& table,
                      py::handle mapping,
                      const std::string& path,
                      void* s);
py::dict TableToDict(const OptionTable& table, const void* s);
bool ValidateTable(const OptionTable& table,
                   const void* s,
                   const std::string& path,
                   std::string* error);
std::string DescribeTable(const OptionTable& table,
                          const void* s,
                          const std::string& indent);

template <typename S>
class StructBinding {
 public:
  explicit StructBinding(const OptionTable& table) : table_(table) {}

  const std::string& cpp_name() const { return table_.struct_name(); }

  // Sets the fields named by the keys of `mapping` (a dict or any Mapping);
  // `path` prefixes field names in messages ("grid.").
  void Update(py::handle mapping, const std::string& path, S* s) const {
    UpdateFromPython(table_, mapping, path, s);
  }
  py::dict ToDict(const S& s) const { return TableToDict(table_, &s); }
  // The children's and the struct's IsValid; false with *error naming the
  // field by its full path.
  bool Validate(const S& s, const std::string& path, std::string* error) const {
    return ValidateTable(table_, &s, path, error);
  }
  // One line per field, "name: type = default", then its help, unit and
  // range; nested structs indented below their name; the defaults are
  // those of `s`.
  std::string Describe(const S& s, const std::string& indent) const {
    return DescribeTable(table_, &s, indent);
  }
  std::vector<std::string> Names() const {
    std::vector<std::string> names;
    for (const OptionField& field : table_.fields()) {
      names.push_back(field.name);
    }
    return names;
  }

 private:
  const OptionTable& table_;
};

}  // namespace python
}  // namespace mlndt
