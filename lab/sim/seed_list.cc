#include "lab/sim/seed_list.h"

#include <glog/logging.h>

#include <algorithm>
#include <charconv>
#include <sstream>

namespace mlndt {
namespace sim {
namespace {

bool ParseSeed(const std::string& text, uint64_t* value) {
  if (text.empty()) return false;
  const char* end = text.data() + text.size();
  const std::from_chars_result r = std::from_chars(text.data(), end, *value);
  return r.ec == std::errc() && r.ptr == end;
}

}  // namespace

bool ParseSeedList(const std::string& text,
                   std::vector<uint64_t>* seeds,
                   std::string* error) {
  CHECK(seeds != nullptr);
  seeds->clear();
  std::stringstream list(text);
  std::string item;
  while (std::getline(list, item, ',')) {
    const size_t dash = item.find('-');
    uint64_t first = 0, last = 0;
    const bool ok = dash == std::string::npos
                        ? ParseSeed(item, &first) && ParseSeed(item, &last)
                        : ParseSeed(item.substr(0, dash), &first) &&
                              ParseSeed(item.substr(dash + 1), &last);
    if (!ok || last < first || last - first >= 100000 ||
        seeds->size() + (last - first + 1) > 100000) {
      *error = "'" + item +
               "': expected a seed or a range a-b (a <= b), at most 100000 "
               "seeds";
      seeds->clear();
      return false;
    }
    for (uint64_t k = 0; k <= last - first; ++k) seeds->push_back(first + k);
  }
  if (seeds->empty() || text.back() == ',') {
    *error = "'" + text + "': expected seeds such as 1000-1009 or 3,5,7";
    seeds->clear();
    return false;
  }
  return true;
}

bool ParseNameList(const std::string& text,
                   std::vector<std::string>* names,
                   std::string* error) {
  CHECK(names != nullptr);
  names->clear();
  std::stringstream list(text);
  std::string item;
  while (std::getline(list, item, ',')) {
    if (item.empty()) break;
    names->push_back(item);
  }
  if (names->empty() || text.back() == ',' ||
      names->size() !=
          static_cast<size_t>(std::count(text.begin(), text.end(), ',') + 1)) {
    *error = "'" + text + "': expected comma-separated names";
    names->clear();
    return false;
  }
  return true;
}

}  // namespace sim
}  // namespace mlndt
