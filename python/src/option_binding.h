#pragma once

// The bridge between the library's option structs and Python keyword
// arguments: one StructBinding per struct lists its fields (name as in the
// C++ header, member pointer, a one-line doc) once, and gives
//   - Update: set the fields named in a dict, strictly typed; an unknown key
//     or a value of the wrong type raises ValueError naming the full path
//     ("grid.finest_cell_size_m");
//   - ToDict: every field, nested structs as dicts, enums as their XToString
//     names (what mlndt.default_options() returns);
//   - Validate: the struct's own IsValid (children first), with the path put
//     into the library's message;
//   - Describe: the field list with types and defaults, for docstrings.
// options.cc holds the bindings of the library's structs, one function each.

#include <pybind11/pybind11.h>

#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

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

// The names of an enum's values through its XToString, which returns
// "UNKNOWN" past the last one (the library's and Ceres' enums count from 0).
template <typename E>
std::vector<std::string> EnumNames(const char* (*to_string)(E)) {
  std::vector<std::string> names;
  for (int i = 0; i < 256; ++i) {
    const std::string name = to_string(static_cast<E>(i));
    if (name == "UNKNOWN") break;
    names.push_back(name);
  }
  return names;
}

template <typename S>
class StructBinding {
 public:
  // `cpp_name`: the struct's C++ name, for docs and messages.
  explicit StructBinding(std::string cpp_name)
      : cpp_name_(std::move(cpp_name)) {}

  const std::string& cpp_name() const { return cpp_name_; }

  // A scalar or list field (bool, integers, double, std::vector<double>).
  template <typename T>
  StructBinding& Field(const char* name, T S::*member, const char* doc) {
    using Codec = OptionCodec<T>;
    Entry entry = MakeEntry(name, doc, Codec::TypeName());
    entry.set = [member, name](
                    py::handle value, const std::string& path, S* s) {
      T parsed{};
      if (!Codec::FromPython(value, &parsed)) {
        ThrowValueError("invalid option: " + path + name + " = " +
                        DescribeValue(value) + "; expected " +
                        Codec::TypeName());
      }
      s->*member = std::move(parsed);
    };
    entry.get = [member](const S& s) { return Codec::ToPython(s.*member); };
    entry.repr = [member](const S& s) { return Codec::Repr(s.*member); };
    entries_.push_back(std::move(entry));
    return *this;
  }

  // An enum field, read with StringToX (case-insensitive) and written with
  // XToString.
  template <typename E, typename FromString>
  StructBinding& EnumField(const char* name,
                           E S::*member,
                           const char* (*to_string)(E),
                           FromString from_string,
                           const char* doc) {
    const std::vector<std::string> names = EnumNames(to_string);
    std::string choices;
    for (size_t i = 0; i < names.size(); ++i) {
      choices += (i ? " | " : "") + names[i];
    }
    Entry entry = MakeEntry(name, doc, "str: " + choices);
    entry.set = [member, name, from_string, choices](
                    py::handle value, const std::string& path, S* s) {
      E parsed{};
      if (!py::isinstance<py::str>(value) ||
          !from_string(value.cast<std::string>(), &parsed)) {
        ThrowValueError("invalid option: " + path + name + " = " +
                        DescribeValue(value) + "; expected one of " + choices +
                        " (any case)");
      }
      s->*member = parsed;
    };
    entry.get = [member, to_string](const S& s) {
      return py::str(to_string(s.*member));
    };
    entry.repr = [member, to_string](const S& s) {
      return std::string("\"") + to_string(s.*member) + "\"";
    };
    entries_.push_back(std::move(entry));
    return *this;
  }

  // A nested struct, given as a dict of its fields.
  template <typename N>
  StructBinding& Nested(const char* name,
                        N S::*member,
                        const StructBinding<N>& binding,
                        const char* doc) {
    Entry entry = MakeEntry(name, doc, "dict (" + binding.cpp_name() + ")");
    entry.nested = true;
    entry.set = [member, name, &binding](
                    py::handle value, const std::string& path, S* s) {
      binding.Update(value, path + name + ".", &(s->*member));
    };
    entry.get = [member, &binding](const S& s) {
      return py::object(binding.ToDict(s.*member));
    };
    entry.validate = [member, name, &binding](const S& s,
                                              const std::string& path,
                                              std::string* error) {
      return binding.Validate(s.*member, path + name + ".", error);
    };
    entry.describe = [member, &binding](const S& s, const std::string& indent) {
      return binding.Describe(s.*member, indent);
    };
    entries_.push_back(std::move(entry));
    return *this;
  }

  // The struct's IsValid, run by Validate after its children's.
  StructBinding& Validator(bool (S::*is_valid)(std::string*) const) {
    is_valid_ = is_valid;
    return *this;
  }

  // Sets the fields named by the keys of `mapping` (a dict or any Mapping);
  // `path` prefixes field names in messages ("grid.").
  void Update(py::handle mapping, const std::string& path, S* s) const {
    if (!py::isinstance<py::dict>(mapping) && !py::hasattr(mapping, "keys")) {
      ThrowValueError("invalid option: " +
                      (path.empty() ? std::string("options")
                                    : path.substr(0, path.size() - 1)) +
                      " = " + DescribeValue(mapping) + "; expected a dict of " +
                      cpp_name_ + " fields (" + FieldNames() + ")");
    }
    const py::dict dict = py::dict(py::reinterpret_borrow<py::object>(mapping));
    for (const auto& item : dict) {
      if (!py::isinstance<py::str>(item.first)) {
        ThrowValueError("invalid option: " + path + DescribeValue(item.first) +
                        ": option names are strings");
      }
      const std::string key = item.first.cast<std::string>();
      const Entry* entry = Find(key);
      if (entry == nullptr) {
        ThrowValueError("unknown option " + path + key + " (" + cpp_name_ +
                        " has: " + FieldNames() + ")");
      }
      entry->set(item.second, path, s);
    }
  }

  py::dict ToDict(const S& s) const {
    py::dict dict;
    for (const Entry& entry : entries_) dict[entry.name.c_str()] = entry.get(s);
    return dict;
  }

  // The children's and the struct's IsValid; false with *error naming the
  // field by its full path. The library writes "invalid option: x = ...";
  // the path goes in front of x.
  bool Validate(const S& s, const std::string& path, std::string* error) const {
    for (const Entry& entry : entries_) {
      if (entry.validate && !entry.validate(s, path, error)) return false;
    }
    if (is_valid_ != nullptr && !(s.*is_valid_)(error)) {
      const std::string prefix = "invalid option: ";
      if (error->compare(0, prefix.size(), prefix) == 0) {
        error->insert(prefix.size(), path);
      } else if (!path.empty()) {
        *error = path.substr(0, path.size() - 1) + ": " + *error;
      }
      return false;
    }
    return true;
  }

  // One line per field, "name: type = default  doc", nested structs
  // indented below their name; the defaults are those of `s`.
  std::string Describe(const S& s, const std::string& indent) const {
    std::ostringstream out;
    for (const Entry& entry : entries_) {
      out << indent << entry.name << ": " << entry.type;
      if (!entry.nested) out << " = " << entry.repr(s);
      out << "\n" << indent << "    " << entry.doc << "\n";
      if (entry.nested) out << entry.describe(s, indent + "    ");
    }
    return out.str();
  }

  std::vector<std::string> Names() const {
    std::vector<std::string> names;
    for (const Entry& entry : entries_) names.push_back(entry.name);
    return names;
  }

 private:
  struct Entry {
    std::string name;
    std::string doc;
    std::string type;
    bool nested = false;
    std::function<void(py::handle, const std::string&, S*)> set;
    std::function<py::object(const S&)> get;
    std::function<std::string(const S&)> repr;
    std::function<bool(const S&, const std::string&, std::string*)> validate;
    std::function<std::string(const S&, const std::string&)> describe;
  };

  static Entry MakeEntry(const char* name, const char* doc, std::string type) {
    Entry entry;
    entry.name = name;
    entry.doc = doc;
    entry.type = std::move(type);
    return entry;
  }

  const Entry* Find(const std::string& name) const {
    for (const Entry& entry : entries_) {
      if (entry.name == name) return &entry;
    }
    return nullptr;
  }

  std::string FieldNames() const {
    std::string names;
    for (size_t i = 0; i < entries_.size(); ++i) {
      names += (i ? ", " : "") + entries_[i].name;
    }
    return names;
  }

  std::string cpp_name_;
  std::vector<Entry> entries_;
  bool (S::*is_valid_)(std::string*) const = nullptr;
};

}  // namespace python
}  // namespace mlndt
