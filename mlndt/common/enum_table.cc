#include "mlndt/common/enum_table.h"

#include <algorithm>
#include <cctype>

namespace mlndt {
namespace {

std::string Upper(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) {
    return static_cast<char>(std::toupper(c));
  });
  return text;
}

std::string Lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) {
    return static_cast<char>(std::tolower(c));
  });
  return text;
}

}  // namespace

EnumTable::EnumTable(std::vector<Name> names, std::vector<Name> aliases)
    : names_(std::move(names)), aliases_(std::move(aliases)) {}

const char* EnumTable::ToString(int value) const {
  for (const Name& name : names_) {
    if (name.value == value) return name.name;
  }
  return "UNKNOWN";
}

bool EnumTable::FromString(std::string text, int* value) const {
  text = Upper(std::move(text));
  for (const std::vector<Name>* list : {&names_, &aliases_}) {
    for (const Name& name : *list) {
      if (text == name.name) {
        *value = name.value;
        return true;
      }
    }
  }
  return false;
}

std::string EnumTable::Alias(int value) const {
  for (const Name& alias : aliases_) {
    if (alias.value == value) return " (" + Lower(alias.name) + ")";
  }
  return "";
}

std::string EnumTable::Choices() const {
  std::string out;
  for (size_t i = 0; i < names_.size(); ++i) {
    if (i > 0) out += i + 1 == names_.size() ? " or " : ", ";
    out += Lower(names_[i].name) + Alias(names_[i].value);
  }
  return out;
}

std::string EnumTable::ChoicesForHelp() const {
  std::string out;
  for (size_t i = 0; i < names_.size(); ++i) {
    out +=
        (i > 0 ? " | " : "") + Lower(names_[i].name) + Alias(names_[i].value);
  }
  return out;
}

}  // namespace mlndt
