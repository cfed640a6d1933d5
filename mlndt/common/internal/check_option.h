#pragma once

// Option checks for `bool Options::IsValid(std::string* error) const`
// (the OPTION_GE / OPTION_GT helpers of ceres/internal/solver.cc). Each one
// returns false from the enclosing function with a message naming the field.
// The comparisons are negated, so NaN fails every check.

#include <cmath>
#include <sstream>
#include <string>

#define MLNDT_OPTION_OP(x, op, y)                                \
  do {                                                           \
    if (!((x)op(y))) {                                           \
      std::ostringstream mlndt_option_message;                   \
      mlndt_option_message << "invalid option: " #x " = " << (x) \
                           << "; it must be " #op " " << (y);    \
      *error = mlndt_option_message.str();                       \
      return false;                                              \
    }                                                            \
  } while (false)

#define MLNDT_OPTION_GE(x, y) MLNDT_OPTION_OP(x, >=, y)
#define MLNDT_OPTION_GT(x, y) MLNDT_OPTION_OP(x, >, y)
#define MLNDT_OPTION_LE(x, y) MLNDT_OPTION_OP(x, <=, y)
#define MLNDT_OPTION_LT(x, y) MLNDT_OPTION_OP(x, <, y)

// lo <= x <= hi (finite bounds make x finite).
#define MLNDT_OPTION_IN_RANGE(x, lo, hi)                                  \
  do {                                                                    \
    if (!((x) >= (lo) && (x) <= (hi))) {                                  \
      std::ostringstream mlndt_option_message;                            \
      mlndt_option_message << "invalid option: " #x " = " << (x)          \
                           << "; it must be in [" << (lo) << ", " << (hi) \
                           << "]";                                        \
      *error = mlndt_option_message.str();                                \
      return false;                                                       \
    }                                                                     \
  } while (false)

// An enum field holds one of its named values (ToString(x) knows it).
#define MLNDT_OPTION_ENUM(x, ToString)                     \
  do {                                                     \
    if (std::string(ToString(x)) == "UNKNOWN") {           \
      *error = "invalid option: " #x " = " +               \
               std::to_string(static_cast<long long>(x)) + \
               " is not a value of its enum";              \
      return false;                                        \
    }                                                      \
  } while (false)
