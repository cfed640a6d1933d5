#include "python/src/errors.h"

#include <pybind11/pybind11.h>

#include <filesystem>
#include <system_error>

namespace mlndt {
namespace python {

void ThrowFileError(const std::string& path, const std::string& message) {
  std::error_code ignored;
  PyObject* type = std::filesystem::exists(path, ignored)
                       ? PyExc_OSError
                       : PyExc_FileNotFoundError;
  PyErr_SetString(type, message.c_str());
  throw pybind11::error_already_set();
}

}  // namespace python
}  // namespace mlndt
