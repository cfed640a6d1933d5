#include "lab/eval/reference_chain.h"

#include <algorithm>

namespace mlndt {
namespace {

// The scans of the chain: from the smallest reference index, each next scan
// is the nearest input index of a pair from the current one.
std::vector<int64_t> ChainedScans(
    const std::map<std::string, ReferencePair>& pairs) {
  std::map<int64_t, int64_t> next;  // reference -> nearest input.
  for (const auto& [key, pair] : pairs) {
    if (pair.input_index <= pair.reference_index) continue;
    auto [it, added] = next.emplace(pair.reference_index, pair.input_index);
    if (!added) it->second = std::min(it->second, pair.input_index);
  }
  std::vector<int64_t> scans;
  if (next.empty()) return scans;
  scans.push_back(next.begin()->first);
  for (auto it = next.begin(); it != next.end(); it = next.find(scans.back())) {
    scans.push_back(it->second);
  }
  return scans;
}

}  // namespace

ReferenceChain ChainReferencePairs(
    const std::map<std::string, ReferencePair>& pairs) {
  ReferenceChain chain;
  chain.scans = ChainedScans(pairs);
  if (chain.scans.size() < 2) return chain;
  chain.poses = {Isometry3d::Identity()};
  for (size_t k = 1; k < chain.scans.size(); ++k) {
    const ReferencePair& pair =
        pairs.at(ReferencePairKey(chain.scans[k - 1], chain.scans[k]));
    chain.poses.push_back(chain.poses.back() * pair.reference_from_input);
  }
  return chain;
}

}  // namespace mlndt
