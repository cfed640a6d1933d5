#pragma once

// The scan pairs mlndt_bench registers, each from one start:
//  - any data set folder (data_dir) that holds a reference_pairs.json
//    (lab/eval/reference_pairs.h; scans in it or in its pcd/, read by
//    lab/eval/dataset.h): its pairs, at most max_pairs of them (smallest
//    steps first);
//  - else the bundled sets under data_dir (the repository's data/):
//      koide3  koide3/251371071.pcd onto koide3/251370668.pcd;
//      kitti   kitti/pcd/<j>.pcd onto kitti/pcd/<i>.pcd for j = i + gap,
//              every gap in kitti_gaps that reference_pairs.json has.
// Starts (lab/eval/suite_plan.h): identity, prior (the pair's
// prior_from_input; pairs without one are skipped) and offsets (the
// reference pushed off by each of `offsets`). The truth of a pair is its
// consensus pose in reference_pairs.json. Each scan is read once and shared
// by the pairs that use it. Errors name the fields as mlndt_bench's flags
// ("--starts: ...").

#include <memory>
#include <string>
#include <vector>

#include "lab/eval/suite_plan.h"
#include "mlndt/cloud/point_cloud.h"
#include "mlndt/common/types.h"

namespace mlndt {

struct ScanPair {
  // The table's group: the set ("koide3", "kitti" or the folder's name),
  // followed by "/<start kind>" unless the start is the identity.
  std::string set;
  std::string label;  // e.g. "000000<-000001 prior".
  std::shared_ptr<const PointCloud> reference;
  std::shared_ptr<const PointCloud> input;
  // The consensus of reference_pairs.json.
  Isometry3d reference_from_input_truth = Isometry3d::Identity();
  Isometry3d initial_reference_from_input = Isometry3d::Identity();
  // Each registration in a child process of its own (bench_child.h).
  bool one_shot = false;
};

// What to load. An empty list is refused (mlndt_bench passes a list flag it
// cannot split as an empty list).
struct BenchPairsOptions {
  std::string data_dir;
  // Bundled mode only: the sets (koide3, kitti) and the kitti frame gaps.
  std::vector<std::string> sets = {"koide3", "kitti"};
  std::vector<int> kitti_gaps = {1};
  std::vector<std::string> starts = {"identity"};  // identity, prior, offsets
  std::string offsets;                             // ParseStartOffsets' syntax.
  int max_pairs = 0;                               // Per folder; 0: all.
};

// True when `dir` holds a reference_pairs.json (the any-folder mode).
bool IsDatasetFolder(const std::string& dir);

// The groups of `pairs` in first-seen order.
std::vector<std::string> BenchSets(const std::vector<ScanPair>& pairs);

// Loads every (pair, start). False with *error naming the flag, file or
// pair on bad flags, unreadable files or when no pair is left.
bool LoadBenchPairs(const BenchPairsOptions& options,
                    std::vector<ScanPair>* pairs,
                    std::string* error);

}  // namespace mlndt
