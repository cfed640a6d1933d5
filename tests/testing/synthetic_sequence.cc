#include "tests/testing/synthetic_sequence.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "mlndt/cloud/io.h"
#include "mlndt/common/pose.h"
#include "tests/testing/scratch_dir.h"
#include "tests/testing/synthetic_scene.h"

namespace mlndt {
namespace testing {

SyntheticSequence WriteSyntheticSequence(const std::string& name,
                                         int num_scans,
                                         int points_per_scan,
                                         const Isometry3d& step_motion) {
  const std::string dir = ScratchPath(name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  SyntheticSequence sequence;
  Isometry3d world_from_scan = Isometry3d::Identity();
  for (int k = 0; k < num_scans; ++k) {
    char file[32];
    std::snprintf(file, sizeof(file), "/%06d.pcd", k);
    const PointCloud scan = TransformCloud(
        world_from_scan.inverse(), StreetScene(points_per_scan, 0.02, 100 + k));
    std::string error;
    EXPECT_TRUE(WritePointCloud(dir + file, scan, &error)) << error;
    sequence.paths.push_back(dir + file);
    sequence.world_from_scan.push_back(world_from_scan);
    world_from_scan = world_from_scan * step_motion;
  }
  return sequence;
}

Isometry3d SmallStepMotion() {
  return PoseVectorToIsometry(PoseVectorFromDegrees(0.4, 0.1, 0, 0, 0, 2));
}

}  // namespace testing
}  // namespace mlndt
