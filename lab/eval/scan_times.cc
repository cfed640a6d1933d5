#include "lab/eval/scan_times.h"

#include <cmath>
#include <fstream>
#include <sstream>

namespace mlndt {

bool ReadScanTimes(const std::string& path,
                   std::vector<double>* stamps_s,
                   std::string* error) {
  stamps_s->clear();
  std::ifstream in(path);
  if (!in) {
    *error = path + ": cannot be read";
    return false;
  }
  std::string line;
  for (size_t n = 1; std::getline(in, line); ++n) {
    std::istringstream fields(line);
    std::string token;
    if (!(fields >> token) || token[0] == '#') continue;
    const std::string where = path + ": line " + std::to_string(n) + ": ";
    char* end = nullptr;
    const double t = std::strtod(token.c_str(), &end);
    std::string rest;
    if (end == token.c_str() || *end != '\0' || (fields >> rest) ||
        !std::isfinite(t)) {
      *error = where + "expected one number of seconds, got '" + line + "'";
      return false;
    }
    if (!stamps_s->empty() && !(t > stamps_s->back())) {
      *error = where + "time " + token + " is not after the previous line's";
      return false;
    }
    stamps_s->push_back(t);
  }
  if (stamps_s->empty()) {
    *error = path + ": no time stamps";
    return false;
  }
  return true;
}

}  // namespace mlndt
