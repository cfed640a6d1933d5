#pragma once

// A trajectory from the pairs of a reference_pairs.json (reference_pairs.h):
// from the smallest reference index, each next scan is the nearest input of
// a pair from the current one ("i_(i+1)", or "0_2", "2_4", ... when the
// scan numbering has gaps); pose 0 is the identity and pose k+1 = pose k *
// reference_from_input of that pair, for as long as a next pair exists.

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "lab/eval/reference_pairs.h"
#include "mlndt/common/types.h"

namespace mlndt {

struct ReferenceChain {
  std::vector<int64_t> scans;     // The chained scan numbers.
  std::vector<Isometry3d> poses;  // first_from_scan, one per scan.
  bool consecutive() const {      // No gap in the scan numbers.
    return scans.empty() || scans.back() - scans.front() + 1 ==
                                static_cast<int64_t>(scans.size());
  }
};

// The chain of `pairs` (fewer than two scans when no pair "i_j", i < j).
ReferenceChain ChainReferencePairs(
    const std::map<std::string, ReferencePair>& pairs);

}  // namespace mlndt
