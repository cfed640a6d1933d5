#pragma once

// The bridge between the library's result tables (mlndt/common/
// result_table.h: every field's name, unit and help, written once) and a
// Python class: one read-only property per field, named as the field, in
// the struct's units, and todict() with every field (nested results as
// dicts, lists of them as lists of dicts, vectors and matrices as numpy
// arrays, enums as their names). A field added to a struct's table is a
// property here with no change.

#include <pybind11/pybind11.h>

#include <string>

#include "mlndt/common/result_table.h"

namespace mlndt {
namespace python {

namespace py = pybind11;

// One value as a Python object.
py::object ResultValueToPython(const ResultValue& value);

// Every field of `object` (a struct of `table`), in the table's order.
py::dict ResultDict(const ResultTable& table, const void* object);

// The property's docstring: help, then the unit in brackets.
std::string ResultFieldDoc(const ResultField& field);

// Defines the properties and todict() of `cls` from `table` (S's).
template <typename S>
void DefineResultProperties(py::class_<S>& cls, const ResultTable& table) {
  for (const ResultField& field : table.fields()) {
    const ResultField* f = &field;
    cls.def_property_readonly(
        field.name.c_str(),
        [f](const S& s) { return ResultValueToPython(f->Get(s)); },
        ResultFieldDoc(field).c_str());
  }
  const ResultTable* t = &table;
  cls.def(
      "todict",
      [t](const S& s) { return ResultDict(*t, static_cast<const void*>(&s)); },
      "todict() -> dict\n\nEvery field of the result, named and valued as "
      "its property; nested results as dicts (the keys of the tools' JSON).");
}

}  // namespace python
}  // namespace mlndt
