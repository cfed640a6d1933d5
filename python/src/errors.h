#pragma once

// The library's file errors as Python exceptions: the library's message,
// FileNotFoundError when `path` does not exist (a reader's failure), else
// OSError.

#include <string>

namespace mlndt {
namespace python {

[[noreturn]] void ThrowFileError(const std::string& path,
                                 const std::string& message);

}  // namespace python
}  // namespace mlndt
