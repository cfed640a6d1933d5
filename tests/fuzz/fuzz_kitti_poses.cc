// libFuzzer target: KITTI pose files (ReadKittiPoses on a scratch file). A
// file that reads is written with WriteKittiPoses and read back: the same
// doubles must come back (the writer's 17 digits round-trip exactly).
// Seeds: tests/fuzz/corpus/kitti_poses/. Run by .ci/fuzz.

#include "mlndt/cloud/pose_io.h"
#include "tests/fuzz/fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* bytes, size_t size) {
  static const std::string path = mlndt::fuzz::ScratchPath("poses.txt");
  static const std::string again_path =
      mlndt::fuzz::ScratchPath("poses_again.txt");
  mlndt::fuzz::WriteScratch(
      path, std::string(reinterpret_cast<const char*>(bytes), size));
  std::vector<Eigen::Isometry3d> poses;
  std::string error;
  if (!mlndt::ReadKittiPoses(path, &poses, &error)) {
    MLNDT_FUZZ_CHECK(poses.empty() && !error.empty());
    return 0;
  }
  MLNDT_FUZZ_CHECK(!poses.empty());
  MLNDT_FUZZ_CHECK(mlndt::WriteKittiPoses(again_path, poses, &error));
  std::vector<Eigen::Isometry3d> again;
  MLNDT_FUZZ_CHECK(mlndt::ReadKittiPoses(again_path, &again, &error));
  MLNDT_FUZZ_CHECK(again.size() == poses.size());
  for (size_t i = 0; i < poses.size(); ++i) {
    MLNDT_FUZZ_CHECK(again[i].matrix() == poses[i].matrix());
  }
  return 0;
}
