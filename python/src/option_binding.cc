#include "python/src/option_binding.h"

namespace mlndt {
namespace python {

void ThrowValueError(const std::string& message) {
  throw py::value_error(message);
}

std::string DescribeValue(py::handle value) {
  std::string repr = py::repr(value).cast<std::string>();
  if (repr.size() > 60) repr = repr.substr(0, 57) + "...";
  return repr + " (" +
         py::str(py::type::handle_of(value).attr("__name__"))
             .cast<std::string>() +
         ")";
}

namespace {

bool IsInstance(py::handle value, const char* module, const char* name) {
  return py::isinstance(value, py::module_::import(module).attr(name));
}

}  // namespace

bool IsBoolLike(py::handle value) {
  return PyBool_Check(value.ptr()) || IsInstance(value, "numpy", "bool_");
}

bool IsIntegerLike(py::handle value) {
  return !IsBoolLike(value) &&
         (PyLong_Check(value.ptr()) || IsInstance(value, "numpy", "integer"));
}

bool IsRealLike(py::handle value) {
  return !IsBoolLike(value) && IsInstance(value, "numbers", "Real");
}

namespace {

// "CERES | NEWTON | LEVENBERG_MARQUARDT".
std::string EnumChoices(const EnumTable& table) {
  std::string choices;
  for (const EnumTable::Name& name : table.names()) {
    choices += (choices.empty() ? "" : " | ") + std::string(name.name);
  }
  return choices;
}

std::string TypeName(const OptionField& field) {
  switch (field.type) {
    case OptionType::BOOL:
      return OptionCodec<bool>::TypeName();
    case OptionType::INT:
    case OptionType::UINT64:
      return OptionCodec<int>::TypeName();
    case OptionType::DOUBLE:
      return OptionCodec<double>::TypeName();
    case OptionType::DOUBLE_LIST:
      return OptionCodec<std::vector<double>>::TypeName();
    case OptionType::ENUM:
      return "str: " + EnumChoices(*field.enum_table);
    case OptionType::STRUCT:
      break;
  }
  return "dict (" + field.nested->struct_name() + ")";
}

template <typename T>
bool Read(py::handle value, void* p) {
  return OptionCodec<T>::FromPython(value, static_cast<T*>(p));
}

// Sets a scalar, list or enum field; false for a value of the wrong type.
bool SetField(const OptionField& field, py::handle value, void* p) {
  switch (field.type) {
    case OptionType::BOOL:
      return Read<bool>(value, p);
    case OptionType::INT:
      return Read<int>(value, p);
    case OptionType::UINT64:
      return Read<uint64_t>(value, p);
    case OptionType::DOUBLE:
      return Read<double>(value, p);
    case OptionType::DOUBLE_LIST:
      return Read<std::vector<double>>(value, p);
    case OptionType::ENUM: {
      int parsed = 0;
      if (!py::isinstance<py::str>(value) ||
          !field.enum_table->FromString(value.cast<std::string>(), &parsed)) {
        return false;
      }
      field.set_enum(p, parsed);
      return true;
    }
    case OptionType::STRUCT:
      break;
  }
  return false;
}

template <typename T>
py::object Write(const void* p) {
  return OptionCodec<T>::ToPython(*static_cast<const T*>(p));
}

py::object GetField(const OptionField& field, const void* p) {
  switch (field.type) {
    case OptionType::BOOL:
      return Write<bool>(p);
    case OptionType::INT:
      return Write<int>(p);
    case OptionType::UINT64:
      return Write<uint64_t>(p);
    case OptionType::DOUBLE:
      return Write<double>(p);
    case OptionType::DOUBLE_LIST:
      return Write<std::vector<double>>(p);
    case OptionType::ENUM:
      return py::str(field.enum_table->ToString(field.get_enum(p)));
    case OptionType::STRUCT:
      break;
  }
  return TableToDict(*field.nested, p);
}

template <typename T>
std::string ReprOf(const void* p) {
  return OptionCodec<T>::Repr(*static_cast<const T*>(p));
}

std::string Repr(const OptionField& field, const void* p) {
  switch (field.type) {
    case OptionType::BOOL:
      return ReprOf<bool>(p);
    case OptionType::INT:
      return ReprOf<int>(p);
    case OptionType::UINT64:
      return ReprOf<uint64_t>(p);
    case OptionType::DOUBLE:
      return ReprOf<double>(p);
    case OptionType::DOUBLE_LIST:
      return ReprOf<std::vector<double>>(p);
    case OptionType::ENUM:
      return std::string("\"") + field.enum_table->ToString(field.get_enum(p)) +
             "\"";
    case OptionType::STRUCT:
      break;
  }
  return "";
}

std::string FieldNames(const OptionTable& table) {
  std::string names;
  for (const OptionField& field : table.fields()) {
    names += (names.empty() ? "" : ", ") + field.name;
  }
  return names;
}

void SetFromPython(const OptionField& field,
                   py::handle value,
                   const std::string& path,
                   void* s) {
  void* p = field.locate(s);
  if (field.type == OptionType::STRUCT) {
    UpdateFromPython(*field.nested, value, path + field.name + ".", p);
    return;
  }
  if (SetField(field, value, p)) return;
  const std::string expected =
      field.type == OptionType::ENUM
          ? "one of " + EnumChoices(*field.enum_table) + " (any case)"
          : TypeName(field);
  ThrowValueError("invalid option: " + path + field.name + " = " +
                  DescribeValue(value) + "; expected " + expected);
}

}  // namespace

void UpdateFromPython(const OptionTable& table,
                      py::handle mapping,
                      const std::string& path,
                      void* s) {
  if (!py::isinstance<py::dict>(mapping) && !py::hasattr(mapping, "keys")) {
    ThrowValueError("invalid option: " +
                    (path.empty() ? std::string("options")
                                  : path.substr(0, path.size() - 1)) +
                    " = " + DescribeValue(mapping) + "; expected a dict of " +
                    table.struct_name() + " fields (" + FieldNames(table) +
                    ")");
  }
  const py::dict dict = py::dict(py::reinterpret_borrow<py::object>(mapping));
  for (const auto& item : dict) {
    if (!py::isinstance<py::str>(item.first)) {
      ThrowValueError("invalid option: " + path + DescribeValue(item.first) +
                      ": option names are strings");
    }
    const std::string key = item.first.cast<std::string>();
    const OptionField* field = table.Find(key);
    if (field == nullptr) {
      ThrowValueError("unknown option " + path + key + " (" +
                      table.struct_name() + " has: " + FieldNames(table) + ")");
    }
    SetFromPython(*field, item.second, path, s);
  }
}

py::dict TableToDict(const OptionTable& table, const void* s) {
  py::dict dict;
  for (const OptionField& field : table.fields()) {
    dict[field.name.c_str()] =
        GetField(field, field.locate(const_cast<void*>(s)));
  }
  return dict;
}

bool ValidateTable(const OptionTable& table,
                   const void* s,
                   const std::string& path,
                   std::string* error) {
  for (const OptionField& field : table.fields()) {
    if (field.type == OptionType::STRUCT &&
        !ValidateTable(*field.nested,
                       field.locate(const_cast<void*>(s)),
                       path + field.name + ".",
                       error)) {
      return false;
    }
  }
  const bool valid = table.is_valid() ? table.is_valid()(s, error)
                                      : table.CheckRanges(s, error);
  if (valid) return true;
  // The library writes "invalid option: x = ..."; the path goes before x.
  const std::string prefix = "invalid option: ";
  if (error->compare(0, prefix.size(), prefix) == 0) {
    error->insert(prefix.size(), path);
  } else if (!path.empty()) {
    *error = path.substr(0, path.size() - 1) + ": " + *error;
  }
  return false;
}

std::string DescribeTable(const OptionTable& table,
                          const void* s,
                          const std::string& indent) {
  std::ostringstream out;
  for (const OptionField& field : table.fields()) {
    const void* p = field.locate(const_cast<void*>(s));
    out << indent << field.name << ": " << TypeName(field);
    if (field.type != OptionType::STRUCT) out << " = " << Repr(field, p);
    out << "\n" << indent << "    " << field.FullHelp() << "\n";
    if (field.type == OptionType::STRUCT) {
      out << DescribeTable(*field.nested, p, indent + "    ");
    }
  }
  return out.str();
}

}  // namespace python
}  // namespace mlndt
