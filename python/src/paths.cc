// PathString (module.h): the path arguments of every function.

#include <pybind11/pybind11.h>

#include <string>

#include "python/src/module.h"

namespace mlndt {
namespace python {

std::string PathString(const py::object& path) {
  const py::object text = py::module_::import("os").attr("fspath")(path);
  if (!py::isinstance<py::str>(text)) {
    throw py::type_error("path: expected a str or os.PathLike of str, got " +
                         py::repr(path).cast<std::string>());
  }
  return text.cast<std::string>();
}

}  // namespace python
}  // namespace mlndt
