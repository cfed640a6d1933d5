#include "tools/cli/list_flags.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "lab/report/text_format.h"

namespace mlndt {
namespace tools {

bool SplitList(const std::string& text, std::vector<std::string>* items) {
  items->clear();
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    const size_t begin = item.find_first_not_of(" \t");
    if (begin == std::string::npos) return false;
    items->push_back(
        item.substr(begin, item.find_last_not_of(" \t") - begin + 1));
  }
  return !items->empty() && text.back() != ',';
}

bool ParseNumberList(const std::string& text, std::vector<double>* values) {
  values->clear();
  if (text.empty()) return true;
  size_t begin = 0;
  while (true) {
    const size_t comma = text.find(',', begin);
    const std::string item = text.substr(
        begin, comma == std::string::npos ? std::string::npos : comma - begin);
    // An empty item: "1,,2", a leading or a trailing comma.
    if (item.find_first_not_of(" \t") == std::string::npos) return false;
    try {
      size_t used = 0;
      const double v = std::stod(item, &used);
      if (item.find_first_not_of(" \t", used) != std::string::npos) {
        return false;
      }
      if (!std::isfinite(v)) return false;
      values->push_back(v);
    } catch (...) {
      return false;
    }
    if (comma == std::string::npos) return true;
    begin = comma + 1;
  }
}

bool ParseIntList(const std::string& text, std::vector<int>* values) {
  std::vector<std::string> items;
  if (!SplitList(text, &items)) return false;
  values->clear();
  for (const std::string& item : items) {
    try {
      size_t used = 0;
      const int v = std::stoi(item, &used);
      if (used != item.size()) return false;
      values->push_back(v);
    } catch (...) {
      return false;
    }
  }
  return true;
}

bool ParseCountList(const std::string& text,
                    size_t min_value,
                    size_t max_value,
                    std::vector<size_t>* values,
                    std::string* error) {
  values->clear();
  const std::string range = "a whole number in [" + std::to_string(min_value) +
                            ", " + std::to_string(max_value) + "]";
  std::vector<std::string> items;
  if (!SplitList(text, &items)) {
    *error = "expected comma-separated items, each " + range;
    return false;
  }
  for (const std::string& item : items) {
    errno = 0;
    const unsigned long long v = std::strtoull(item.c_str(), nullptr, 10);
    if (item.find_first_not_of("0123456789") != std::string::npos ||
        errno == ERANGE || v < min_value || v > max_value) {
      *error = "'" + item + "' is not " + range;
      return false;
    }
    values->push_back(static_cast<size_t>(v));
  }
  return true;
}

bool ParseSizes(const std::string& text,
                std::vector<size_t>* sizes,
                std::string* error) {
  std::vector<double> values;
  if (!ParseNumberList(text, &values) || values.empty()) {
    *error = "--sizes=" + text +
             ": expected comma-separated positive integers, e.g. 10000,30000";
    return false;
  }
  sizes->clear();
  for (double v : values) {
    if (!(v >= 1) || v != std::floor(v) || v > 1e12) {
      *error =
          "--sizes=" + text + ": '" + Num(v) + "' is not a positive integer";
      return false;
    }
    const size_t n = static_cast<size_t>(v);
    if (!sizes->empty() && n <= sizes->back()) {
      *error = "--sizes=" + text + ": sizes must be strictly increasing (" +
               std::to_string(n) + " after " + std::to_string(sizes->back()) +
               ")";
      return false;
    }
    sizes->push_back(n);
  }
  return true;
}

bool SplitFileList(const std::string& flag,
                   const std::string& text,
                   std::vector<std::string>* files,
                   std::string* error) {
  std::stringstream list(text);
  std::string item;
  while (std::getline(list, item, ',')) {
    if (item.empty()) {
      *error = flag + "=" + text + ": an empty file name";
      return false;
    }
    files->push_back(item);
  }
  return true;
}

bool ParseLengthList(const std::string& flag,
                     const std::string& text,
                     std::vector<double>* lengths,
                     std::string* error) {
  if (!ParseNumberList(text, lengths) || lengths->empty() ||
      std::any_of(lengths->begin(), lengths->end(), [](double l) {
        return !(l > 0.0);
      })) {
    *error = flag + "=" + text + ": expected comma-separated lengths > 0 [m]";
    return false;
  }
  std::vector<double> sorted = *lengths;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
    *error = flag + "=" + text + ": a length is given twice";
    return false;
  }
  return true;
}

}  // namespace tools
}  // namespace mlndt
