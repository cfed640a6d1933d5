#pragma once

// The library's file errors as Python exceptions with the library's message:
// FileNotFoundError when `path` (for a writer: its folder) does not exist,
// else OSError.

#include <string>

namespace mlndt {
namespace python {

[[noreturn]] void ThrowReadError(const std::string& path,
                                 const std::string& message);
[[noreturn]] void ThrowWriteError(const std::string& path,
                                  const std::string& message);

}  // namespace python
}  // namespace mlndt
