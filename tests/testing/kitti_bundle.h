#pragma once

// The bundled KITTI 00 frames 0-7 (data/kitti): their scans and poses, read
// once per call; a read failure is a test failure.

#include <cstddef>
#include <vector>

#include "mlndt/cloud/point_cloud.h"
#include "mlndt/common/types.h"

namespace mlndt {
namespace testing {

// Frame i's scan (0 <= i <= 7), every `stride`-th point.
PointCloud BundledKittiScan(int i, size_t stride = 1);

// poses_velo.txt: world_from_velodyne of frames 0-7.
std::vector<Isometry3d> BundledKittiPoses();

}  // namespace testing
}  // namespace mlndt
