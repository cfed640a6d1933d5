// mlndt_gt_check: checks a ground-truth relative pose against the scans'
// own geometry, independently of any NDT model. For scale factors s it moves
// the input by the ground-truth rotation and s times its translation and
// reports the mean distance of input points to their nearest reference point
// (points within 0.5 m, between --min_range and --max_range, above
// --min_height so that ground rings, which move with the sensor, don't count).
// A consistent ground truth has its minimum at s = 1.
//
//   mlndt_gt_check --reference=000000.pcd --input=000003.pcd
//   --gt_poses=poses.txt
//                  --reference_index=0 --input_index=3

#include <gflags/gflags.h>
#include <glog/logging.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <unordered_map>
#include <vector>

#include "mlndt/cloud/io.h"
#include "mlndt/cloud/pose_io.h"
#include "mlndt/common/fast_floor.h"
#include "mlndt/common/types.h"
#include "tools/cli/tool_main.h"

DEFINE_string(reference, "", "Reference scan");
DEFINE_string(input, "", "Input scan");
DEFINE_string(gt_poses, "", "KITTI poses in the scans' frame");
DEFINE_int32(reference_index, 0, "Line of the reference scan's pose");
DEFINE_int32(input_index, 1, "Line of the input scan's pose");
DEFINE_double(min_range, 5.0, "Input points nearer than this [m] are ignored");
DEFINE_double(max_range,
              40.0,
              "Input points farther than this [m] are ignored");
DEFINE_double(min_height,
              -1.2,
              "Points below this z [m, sensor frame] are ignored");

namespace mlndt {
namespace {

struct KeyHash {
  size_t operator()(const Eigen::Vector3i& k) const {
    return static_cast<size_t>(k.x()) * 73856093u ^
           static_cast<size_t>(k.y()) * 19349663u ^
           static_cast<size_t>(k.z()) * 83492791u;
  }
};

constexpr double kVoxel = 0.5;  // = the nearest-neighbour search radius [m].

Eigen::Vector3i Key(const Eigen::Vector3d& p) {
  return Eigen::Vector3i(static_cast<int>(FloorToInt64(p.x() / kVoxel)),
                         static_cast<int>(FloorToInt64(p.y() / kVoxel)),
                         static_cast<int>(FloorToInt64(p.z() / kVoxel)));
}

int Run() {
  PointCloud reference, input;
  std::vector<Isometry3d> poses;
  std::string error;
  if (!ReadPointCloud(FLAGS_reference, &reference, nullptr, &error) ||
      !ReadPointCloud(FLAGS_input, &input, nullptr, &error) ||
      !ReadKittiPoses(FLAGS_gt_poses, &poses, &error)) {
    std::cerr << "mlndt_gt_check: " << error << "\n";
    return tools::kExitUsage;
  }
  const int n = static_cast<int>(poses.size());
  if (FLAGS_reference_index < 0 || FLAGS_reference_index >= n ||
      FLAGS_input_index < 0 || FLAGS_input_index >= n) {
    std::cerr << "mlndt_gt_check: pose index out of range (" << n
              << " poses)\n";
    return tools::kExitUsage;
  }
  const Isometry3d truth =
      poses[static_cast<size_t>(FLAGS_reference_index)].inverse() *
      poses[static_cast<size_t>(FLAGS_input_index)];
  std::unordered_map<Eigen::Vector3i, std::vector<Eigen::Vector3d>, KeyHash>
      voxels;
  for (const Eigen::Vector3d& p : reference.points()) {
    if (p.z() >= FLAGS_min_height) voxels[Key(p)].push_back(p);
  }
  std::printf("scale  translation[m]  mean_nn[m]  points\n");
  for (double s = 0.6; s <= 1.101; s += 0.05) {
    Isometry3d moved = truth;
    moved.translation() *= s;
    double sum = 0.0;
    int count = 0;
    for (const Eigen::Vector3d& q : input.points()) {
      const double range = q.norm();
      if (range < FLAGS_min_range || range > FLAGS_max_range ||
          q.z() < FLAGS_min_height)
        continue;
      const Eigen::Vector3d p = moved * q;
      const Eigen::Vector3i key = Key(p);
      double best = kVoxel * kVoxel;
      for (int dx = -1; dx <= 1; ++dx) {
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dz = -1; dz <= 1; ++dz) {
            const auto it = voxels.find(key + Eigen::Vector3i(dx, dy, dz));
            if (it == voxels.end()) continue;
            for (const Eigen::Vector3d& r : it->second)
              best = std::min(best, (r - p).squaredNorm());
          }
        }
      }
      if (best < kVoxel * kVoxel) {
        sum += std::sqrt(best);
        ++count;
      }
    }
    std::printf("%5.2f  %14.3f  %10.4f  %6d\n",
                s,
                moved.translation().norm(),
                count ? sum / count : NAN,
                count);
  }
  return 0;
}

}  // namespace
}  // namespace mlndt

int main(int argc, char** argv) {
  if (!mlndt::tools::StartTool(
          "Checks a ground-truth relative pose against the scans' geometry.",
          true,
          &argc,
          &argv)) {
    return mlndt::tools::kExitUsage;
  }
  return mlndt::Run();
}
