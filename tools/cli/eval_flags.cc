#include "tools/cli/eval_flags.h"

#include <algorithm>
#include <sstream>

#include "tools/cli/list_flags.h"

namespace mlndt {
namespace tools {

bool SplitEstimateList(const std::string& text,
                       std::vector<std::string>* files,
                       std::string* error) {
  std::stringstream list(text);
  std::string item;
  while (std::getline(list, item, ',')) {
    if (item.empty()) {
      *error = "--estimate=" + text + ": an empty file name";
      return false;
    }
    files->push_back(item);
  }
  return true;
}

bool ParseSegmentLengths(const std::string& flag,
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
