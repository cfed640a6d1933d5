// libFuzzer target: 3DTK .pose files (Read3dtkPose on a scratch file). What
// reads must be a finite rigid transform.
// Seeds: tests/fuzz/corpus/3dtk_pose/. Run by .ci/fuzz.

#include <cmath>

#include "mlndt/cloud/pose_io.h"
#include "tests/fuzz/fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* bytes, size_t size) {
  static const std::string path = mlndt::fuzz::ScratchPath("scan.pose");
  mlndt::fuzz::WriteScratch(
      path, std::string(reinterpret_cast<const char*>(bytes), size));
  Eigen::Isometry3d world_from_scan;
  std::string error;
  if (!mlndt::Read3dtkPose(path, &world_from_scan, &error)) {
    MLNDT_FUZZ_CHECK(!error.empty());
    return 0;
  }
  // Huge but finite numbers may overflow to inf in the cm -> m and deg -> rad
  // conversions; what must hold is a proper rotation.
  const Eigen::Matrix3d rotation = world_from_scan.linear();
  MLNDT_FUZZ_CHECK(rotation.allFinite());
  MLNDT_FUZZ_CHECK(std::abs(rotation.determinant() - 1.0) < 1e-6);
  return 0;
}
