#pragma once

// mlndt_posegraph --pairs: extra ML-NDT pairs (loop closures) as
// "i:j,i:j,..." of 0-based scan indices in file-name order.

#include <string>
#include <utility>
#include <vector>

namespace mlndt {
namespace tools {

// False with *error quoting the bad entry; "" gives no pairs. Ranges are
// checked by PoseGraphOptions::IsValid (it knows the number of scans).
bool ParseScanPairs(const std::string& text,
                    std::vector<std::pair<int, int>>* pairs,
                    std::string* error);

}  // namespace tools
}  // namespace mlndt
