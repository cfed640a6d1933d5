#pragma once

// Lists of seeds and names as the simulator's program takes them.

#include <cstdint>
#include <string>
#include <vector>

namespace mlndt {
namespace sim {

// "1000-1009", "3,5,7" or a mix ("0-2,10"): each item a seed or an
// inclusive range a-b with a <= b, at most 100000 seeds in all, in the
// order given. False with *error naming the bad item.
bool ParseSeedList(const std::string& text,
                   std::vector<uint64_t>* seeds,
                   std::string* error);

// Comma-separated non-empty names; false with *error on an empty item.
bool ParseNameList(const std::string& text,
                   std::vector<std::string>* names,
                   std::string* error);

}  // namespace sim
}  // namespace mlndt
