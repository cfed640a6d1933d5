#pragma once

// Helpers for the XToString / StringToX pairs every enum gets
// (the shape of ceres/types.h).

#include <algorithm>
#include <cctype>
#include <string>

namespace mlndt {

// Upper-cases `value` in place so that "gbs" and "GBS" both parse.
inline void UpperCase(std::string* value) {
  std::transform(
      value->begin(), value->end(), value->begin(), [](unsigned char c) {
        return static_cast<char>(std::toupper(c));
      });
}

}  // namespace mlndt

// Inside a StringToX function: return true when `value` (upper-cased) names
// X::name.
#define MLNDT_STRING_TO_ENUM(name, Enum) \
  if (value == #name) {                  \
    *result = Enum::name;                \
    return true;                         \
  }
