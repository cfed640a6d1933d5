#include "tests/testing/text_table.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace mlndt {
namespace testing {

std::vector<std::string> Split(const std::string& text, char separator) {
  std::vector<std::string> items;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, separator)) items.push_back(item);
  if (!text.empty() && text.back() == separator) items.push_back("");
  return items;
}

std::vector<std::string> TableCells(const std::string& line) {
  std::vector<std::string> cells;
  for (const std::string& cell : Split(line, '|')) {
    const size_t begin = cell.find_first_not_of(' ');
    if (begin == std::string::npos) continue;
    cells.push_back(cell.substr(begin, cell.find_last_not_of(' ') - begin + 1));
  }
  return cells;
}

double ToNumber(const std::string& text) {
  if (text.empty()) return std::nan("");
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  return *end == '\0' ? value : std::nan("");
}

}  // namespace testing
}  // namespace mlndt
