#pragma once

// A minimal JSON writer for the tools' one-object outputs.

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "mlndt/common/atomic_file.h"

namespace mlndt {
namespace tools {

inline std::string JsonString(const std::string& value) {
  std::ostringstream out;
  out << '"';
  for (const char c : value) {
    switch (c) {
      case '"':
        out << "\\\"";
        break;
      case '\\':
        out << "\\\\";
        break;
      case '\n':
        out << "\\n";
        break;
      case '\t':
        out << "\\t";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          out << "\\u" << std::hex << std::setw(4) << std::setfill('0')
              << int(c) << std::dec;
        } else {
          out << c;
        }
    }
  }
  out << '"';
  return out.str();
}

inline std::string JsonNumber(double value) {
  if (!std::isfinite(value)) return "null";
  std::ostringstream out;
  out << std::setprecision(10) << value;
  return out.str();
}

template <typename Container>
std::string JsonArray(const Container& values) {
  std::string out = "[";
  bool first = true;
  for (const auto& v : values) {
    if (!first) out += ", ";
    out += JsonNumber(static_cast<double>(v));
    first = false;
  }
  return out + "]";
}

// Builds {"key": value, ...} in insertion order; values are raw JSON.
class JsonObject {
 public:
  JsonObject& Add(const std::string& key, const std::string& raw_json) {
    if (!body_.empty()) body_ += ", ";
    body_ += JsonString(key) + ": " + raw_json;
    return *this;
  }
  JsonObject& AddString(const std::string& key, const std::string& value) {
    return Add(key, JsonString(value));
  }
  JsonObject& AddNumber(const std::string& key, double value) {
    return Add(key, JsonNumber(value));
  }
  JsonObject& AddBool(const std::string& key, bool value) {
    return Add(key, value ? "true" : "false");
  }
  std::string str() const { return "{" + body_ + "}"; }

 private:
  std::string body_;
};

// Writes `json` and a newline to `path`; false with *error when it cannot.
inline bool WriteJsonFile(const std::string& path,
                          const std::string& json,
                          std::string* error) {
  return WriteFileAtomically(path, json + "\n", error);
}

}  // namespace tools
}  // namespace mlndt
