// libFuzzer target: KITTI calib.txt, the Tr: line (ReadKittiCalibTr on a
// scratch file). What reads must be a finite rigid transform.
// Seeds: tests/fuzz/corpus/kitti_calib/. Run by .ci/fuzz.

#include <cmath>

#include "mlndt/cloud/pose_io.h"
#include "tests/fuzz/fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* bytes, size_t size) {
  static const std::string path = mlndt::fuzz::ScratchPath("calib.txt");
  mlndt::fuzz::WriteScratch(
      path, std::string(reinterpret_cast<const char*>(bytes), size));
  Eigen::Isometry3d cam0_from_velo;
  std::string error;
  if (!mlndt::ReadKittiCalibTr(path, &cam0_from_velo, &error)) {
    MLNDT_FUZZ_CHECK(!error.empty());
    return 0;
  }
  MLNDT_FUZZ_CHECK(cam0_from_velo.matrix().allFinite());
  MLNDT_FUZZ_CHECK(std::abs(cam0_from_velo.linear().determinant() - 1.0) <
                   1e-2);
  return 0;
}
