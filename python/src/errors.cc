#include "python/src/errors.h"

#include <pybind11/pybind11.h>

#include <filesystem>
#include <system_error>

namespace mlndt {
namespace python {

namespace {

[[noreturn]] void Throw(const std::filesystem::path& must_exist,
                        const std::string& message) {
  std::error_code ignored;
  PyObject* type = std::filesystem::exists(must_exist, ignored)
                       ? PyExc_OSError
                       : PyExc_FileNotFoundError;
  PyErr_SetString(type, message.c_str());
  throw pybind11::error_already_set();
}

}  // namespace

void ThrowReadError(const std::string& path, const std::string& message) {
  Throw(path, message);
}

void ThrowWriteError(const std::string& path, const std::string& message) {
  const std::filesystem::path folder =
      std::filesystem::absolute(path).parent_path();
  Throw(folder, message);
}

}  // namespace python
}  // namespace mlndt
