#pragma once

// One table per enum: its values' names, written once. The XToString /
// StringToX pairs of every enum (the shape of ceres/types.h), the choices
// listed by error messages, the flags' --help and the Python docstrings all
// read it.

#include <string>
#include <utility>
#include <vector>

namespace mlndt {

class EnumTable {
 public:
  struct Name {
    int value;
    const char* name;  // UPPER_CASE, as the enum value.
  };

  // `names`: every value with its name; `aliases`: more names StringToX
  // accepts for a value ("LM" for LEVENBERG_MARQUARDT).
  EnumTable(std::vector<Name> names, std::vector<Name> aliases = {});

  // The value's name, "UNKNOWN" for a value not in the table.
  const char* ToString(int value) const;
  // Any case; false (and *value untouched) for a name not in the table.
  bool FromString(std::string text, int* value) const;
  // The names in lower case for messages: "none, huber or cauchy"; an alias
  // follows its value's name in parentheses.
  std::string Choices() const;
  // The names in lower case, separated by " | " (for --help).
  std::string ChoicesForHelp() const;

  const std::vector<Name>& names() const { return names_; }

 private:
  std::string Alias(int value) const;

  std::vector<Name> names_;
  std::vector<Name> aliases_;
};

// The typed front of an EnumTable, for the XToString / StringToX functions.
template <typename E>
const char* EnumToString(const EnumTable& table, E value) {
  return table.ToString(static_cast<int>(value));
}

template <typename E>
bool StringToEnum(const EnumTable& table, std::string text, E* value) {
  int parsed = 0;
  if (!table.FromString(std::move(text), &parsed)) return false;
  *value = static_cast<E>(parsed);
  return true;
}

// The table of an enum whose XToString returns "UNKNOWN" past its last value
// and counts from 0 (Ceres' enums).
template <typename E>
EnumTable EnumTableFromToString(const char* (*to_string)(E)) {
  std::vector<EnumTable::Name> names;
  for (int i = 0; i < 256; ++i) {
    const char* name = to_string(static_cast<E>(i));
    if (std::string(name) == "UNKNOWN") break;
    names.push_back({i, name});
  }
  return EnumTable(std::move(names));
}

}  // namespace mlndt
