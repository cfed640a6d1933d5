#pragma once

// Option checks for `bool Options::IsValid(std::string* error) const`
// (the OPTION_GE / OPTION_GT helpers of ceres/internal/solver.cc). Each one
// returns false from the enclosing function with a message naming the field.

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
