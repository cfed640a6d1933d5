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

}  // namespace python
}  // namespace mlndt
