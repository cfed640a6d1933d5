#pragma once

// The scan pairs mlndt_bench registers (from --data_dir, the repository's
// data/ by default):
//   koide3  koide3/251371071.pcd onto koide3/251370668.pcd; truth:
//           koide3/T_target_source.txt, the reference result shipped with the
//           pair (there is no independent ground truth).
//   kitti   kitti/pcd/<j>.pcd onto kitti/pcd/<i>.pcd for j = i + gap, every
//           gap in --kitti_gaps; truth V_i^-1 V_j from kitti/poses_velo.txt.

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
