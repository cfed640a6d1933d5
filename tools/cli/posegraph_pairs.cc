#include "tools/cli/posegraph_pairs.h"

#include <sstream>

namespace mlndt {
namespace tools {
namespace {

bool ParseIndex(const std::string& text, int* value) {
  if (text.empty() ||
      text.find_first_not_of("0123456789") != std::string::npos ||
      text.size() > 9) {
    return false;
  }
  *value = std::stoi(text);
  return true;
}

}  // namespace

bool ParseScanPairs(const std::string& text,
                    std::vector<std::pair<int, int>>* pairs,
                    std::string* error) {
  pairs->clear();
  if (text.empty()) return true;
  std::stringstream stream(text);
  std::string entry;
  while (std::getline(stream, entry, ',')) {
    const size_t colon = entry.find(':');
    int i = 0, j = 0;
    if (colon == std::string::npos || !ParseIndex(entry.substr(0, colon), &i) ||
        !ParseIndex(entry.substr(colon + 1), &j)) {
      *error = "'" + entry + "': expected i:j (0-based scan indices)";
      return false;
    }
    pairs->emplace_back(i, j);
  }
  if (text.back() == ',') {
    *error = "'" + text + "': trailing comma";
    return false;
  }
  return true;
}

}  // namespace tools
}  // namespace mlndt
