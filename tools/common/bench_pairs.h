#pragma once

// The scan pairs mlndt_bench registers (from --data_dir, the repository's
// data/ by default):
//   koide3  koide3/251371071.pcd onto koide3/251370668.pcd;
//   kitti   kitti/pcd/<j>.pcd onto kitti/pcd/<i>.pcd for j = i + gap, every
//           gap in --kitti_gaps that reference_pairs.json has.
// The truth of a pair is its consensus pose in <set>/reference_pairs.json
// (KITTI's official poses for these frames are a constant-velocity fill).

#include <string>
#include <vector>

#include "mlndt/cloud/point_cloud.h"
#include "mlndt/common/types.h"

namespace mlndt {
namespace tools {

struct ScanPair {
  std::string set;    // "koide3" or "kitti".
  std::string label;  // e.g. "000000<-000001".
  PointCloud reference;
  PointCloud input;
  // The consensus of reference_pairs.json.
  Isometry3d reference_from_input_truth = Isometry3d::Identity();
};

// --pairs: "koide3", "kitti" or both, returned in that fixed order without
// repeats.
bool ParseBenchSets(const std::string& text,
                    std::vector<std::string>* sets,
                    std::string* error);

// Reads the pairs of `sets` (ParseBenchSets) from `dir`; `kitti_gaps` is
// the comma-separated list of KITTI frame gaps.
bool LoadBenchPairs(const std::string& dir,
                    const std::vector<std::string>& sets,
                    const std::string& kitti_gaps,
                    std::vector<ScanPair>* pairs,
                    std::string* error);

}  // namespace tools
}  // namespace mlndt
