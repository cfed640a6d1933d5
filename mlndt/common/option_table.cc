#include "mlndt/common/option_table.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace mlndt {
namespace {

// A number as IsValid's messages always wrote it (std::ostream defaults).
std::string Short(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

// The shortest text that reads back as exactly `x`.
std::string Exact(double x) {
  for (int precision = 6; precision < 18; ++precision) {
    std::ostringstream out;
    out.precision(precision);
    out << x;
    if (std::strtod(out.str().c_str(), nullptr) == x) return out.str();
  }
  return Short(x);
}

bool ParseDouble(const std::string& text, double* value) {
  if (text.empty()) return false;
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(text.c_str(), &end);
  if (*end != '\0' || errno == ERANGE) return false;
  *value = v;
  return true;
}

bool ParseDoubleList(const std::string& text, std::vector<double>* values) {
  values->clear();
  if (text.empty()) return true;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    double v = 0.0;
    if (!ParseDouble(item, &v)) return false;
    values->push_back(v);
  }
  return text.back() != ',';
}

std::string TypeText(const OptionField& field) {
  switch (field.type) {
    case OptionType::BOOL:
      return "true or false";
    case OptionType::INT:
    case OptionType::UINT64:
      return "an integer";
    case OptionType::DOUBLE:
      return "a number";
    case OptionType::DOUBLE_LIST:
      return "comma-separated numbers";
    case OptionType::ENUM:
      return field.enum_table->Choices();
    case OptionType::STRUCT:
      break;
  }
  return "a struct";
}

bool ParseValue(const OptionField& field, const std::string& text, void* p) {
  double v = 0.0;
  switch (field.type) {
    case OptionType::BOOL:
      if (text != "true" && text != "false") return false;
      *static_cast<bool*>(p) = text == "true";
      return true;
    case OptionType::INT:
      if (!ParseDouble(text, &v) || v != std::floor(v) || v < INT32_MIN ||
          v > INT32_MAX) {
        return false;
      }
      *static_cast<int*>(p) = static_cast<int>(v);
      return true;
    case OptionType::UINT64: {
      if (text.empty() || text[0] == '-') return false;
      char* end = nullptr;
      errno = 0;
      const unsigned long long u = std::strtoull(text.c_str(), &end, 10);
      if (*end != '\0' || errno == ERANGE) return false;
      *static_cast<uint64_t*>(p) = u;
      return true;
    }
    case OptionType::DOUBLE:
      return ParseDouble(text, static_cast<double*>(p));
    case OptionType::DOUBLE_LIST:
      return ParseDoubleList(text, static_cast<std::vector<double>*>(p));
    case OptionType::ENUM: {
      int value = 0;
      if (!field.enum_table->FromString(text, &value)) return false;
      field.set_enum(p, value);
      return true;
    }
    case OptionType::STRUCT:
      break;
  }
  return false;
}

std::string OutOfRange(const std::string& name,
                       const std::string& value,
                       const std::string& requirement) {
  return "invalid option: " + name + " = " + value + "; it must be " +
         requirement;
}

}  // namespace

bool OptionRange::Contains(double x) const {
  if (or_zero && x == 0.0) return true;
  const bool above = lo_open ? x > lo : x >= lo;
  const bool below = hi_open ? x < hi : x <= hi;
  return above && below;
}

std::string OptionRange::ToString() const {
  std::string text;
  if (std::isinf(lo) && std::isinf(hi)) {
    text = "any number";
  } else if (std::isinf(hi)) {
    text = std::string(lo_open ? "> " : ">= ") + Short(lo);
  } else if (std::isinf(lo)) {
    text = std::string(hi_open ? "< " : "<= ") + Short(hi);
  } else {
    text = std::string("in ") + (lo_open ? "(" : "[") + Short(lo) + ", " +
           Short(hi) + (hi_open ? ")" : "]");
  }
  return or_zero ? text + " or 0" : text;
}

OptionRange Closed(double lo, double hi) { return {lo, hi, false, false}; }
OptionRange LeftOpen(double lo, double hi) { return {lo, hi, true, false}; }
OptionRange RightOpen(double lo, double hi) { return {lo, hi, false, true}; }
OptionRange AtLeast(double lo) {
  return {lo, std::numeric_limits<double>::infinity(), false, false};
}
OptionRange ClosedOrZero(double lo, double hi) {
  return {lo, hi, false, false, true};
}

std::string OptionField::Format(const void* s) const {
  const void* p = locate(const_cast<void*>(s));
  switch (type) {
    case OptionType::BOOL:
      return *static_cast<const bool*>(p) ? "true" : "false";
    case OptionType::INT:
      return std::to_string(*static_cast<const int*>(p));
    case OptionType::UINT64:
      return std::to_string(*static_cast<const uint64_t*>(p));
    case OptionType::DOUBLE:
      return Exact(*static_cast<const double*>(p));
    case OptionType::DOUBLE_LIST: {
      std::string text;
      for (const double v : *static_cast<const std::vector<double>*>(p)) {
        text += (text.empty() ? "" : ",") + Exact(v);
      }
      return text;
    }
    case OptionType::ENUM: {
      std::string name = enum_table->ToString(get_enum(p));
      for (char& c : name) c = static_cast<char>(std::tolower(c));
      return name;
    }
    case OptionType::STRUCT:
      break;
  }
  return "";
}

bool OptionField::Parse(const std::string& text,
                        void* s,
                        std::string* error) const {
  if (ParseValue(*this, text, locate(s))) return true;
  *error = "expected " + TypeText(*this);
  return false;
}

bool OptionField::CheckRange(const void* s,
                             const std::string& prefix,
                             std::string* error) const {
  const void* p = locate(const_cast<void*>(s));
  if (type == OptionType::ENUM) {
    const int value = get_enum(p);
    if (std::string(enum_table->ToString(value)) != "UNKNOWN") return true;
    *error = "invalid option: " + prefix + name + " = " +
             std::to_string(value) + " is not a value of its enum (" +
             enum_table->Choices() + ")";
    return false;
  }
  if (!has_range) return true;
  if (type == OptionType::DOUBLE_LIST) {
    const auto& values = *static_cast<const std::vector<double>*>(p);
    for (size_t i = 0; i < values.size(); ++i) {
      if (range.Contains(values[i])) continue;
      *error = OutOfRange(prefix + name + "[" + std::to_string(i) + "]",
                          Short(values[i]),
                          range.ToString());
      return false;
    }
    return true;
  }
  const double value =
      type == OptionType::INT ? *static_cast<const int*>(p)
      : type == OptionType::UINT64
          ? static_cast<double>(*static_cast<const uint64_t*>(p))
          : *static_cast<const double*>(p);
  if (range.Contains(value)) return true;
  *error = OutOfRange(prefix + name, Short(value), range.ToString());
  return false;
}

std::string OptionField::RangeText() const {
  std::string text;
  if (!unit.empty()) text = "[" + unit + "]";
  if (type == OptionType::ENUM) {
    text += (text.empty() ? "" : " ") + std::string("One of: ") +
            enum_table->ChoicesForHelp() + ".";
  } else if (has_range && !(std::isinf(range.lo) && std::isinf(range.hi))) {
    std::string r = range.ToString();
    r[0] = static_cast<char>(std::toupper(r[0]));
    text += (text.empty() ? "" : " ") +
            std::string(type == OptionType::DOUBLE_LIST ? "Each " : "") +
            (type == OptionType::DOUBLE_LIST ? range.ToString() : r) + ".";
  }
  return text;
}

std::string OptionField::FullHelp() const {
  const std::string range_text = RangeText();
  return range_text.empty() ? help : help + " " + range_text;
}

const OptionField* OptionTable::Find(const std::string& name) const {
  for (const OptionField& field : fields_) {
    if (field.name == name) return &field;
  }
  return nullptr;
}

const OptionField* OptionTable::FindPath(const std::string& path,
                                         const void* s,
                                         const void** owner) const {
  const size_t dot = path.find('.');
  const OptionField* field = Find(path.substr(0, dot));
  if (field == nullptr) return nullptr;
  if (dot == std::string::npos) {
    if (owner != nullptr) *owner = s;
    return field;
  }
  if (field->type != OptionType::STRUCT) return nullptr;
  const void* child =
      s == nullptr ? nullptr : field->locate(const_cast<void*>(s));
  return field->nested->FindPath(path.substr(dot + 1), child, owner);
}

bool OptionTable::CheckRanges(const void* s, std::string* error) const {
  return CheckRangesWithPrefix(s, "", error);
}

bool OptionTable::CheckRangesWithPrefix(const void* s,
                                        const std::string& prefix,
                                        std::string* error) const {
  for (const OptionField& field : fields_) {
    if (field.type != OptionType::STRUCT) {
      if (!field.CheckRange(s, prefix, error)) return false;
    } else if (!field.nested->is_valid()) {
      const void* child = field.locate(const_cast<void*>(s));
      if (!field.nested->CheckRangesWithPrefix(
              child, prefix + field.name + ".", error)) {
        return false;
      }
    }
  }
  return true;
}

}  // namespace mlndt
