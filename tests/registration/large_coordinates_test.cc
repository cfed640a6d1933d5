// Registration in a frame far from the origin (UTM and other projected map
// frames): the bundled koide3 and KITTI pairs moved by (C, C, 0) for C up to
// 4e6 m give the relative pose they give at the origin (within 1 mm and
// 0.01 deg), read from float64 PCD files; float32 files where float32 holds
// the coordinates (1e3 m). Before the solve moved to the input's centroid,
// the rotation was lost from C = 1e5 m on.

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>

#include "mlndt/cloud/io.h"
#include "mlndt/common/pose.h"
#include "mlndt/registration/registration.h"
#include "tests/testing/scratch_dir.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

// A binary PCD with float64 x y z (the library's writers store float32).
void WriteFloat64Pcd(const std::string& path, const PointCloud& cloud) {
  std::ofstream out(path, std::ios::binary);
  out << "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 8 8 8\nTYPE F F F\n"
         "COUNT 1 1 1\nWIDTH "
      << cloud.size() << "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS "
      << cloud.size() << "\nDATA binary\n";
  for (const Eigen::Vector3d& p : cloud.points()) {
    out.write(reinterpret_cast<const char*>(p.data()), 3 * sizeof(double));
  }
  ASSERT_TRUE(out.good());
}

PointCloud Read(const std::string& path) {
  PointCloud cloud;
  std::string error;
  EXPECT_TRUE(ReadPointCloud(path, &cloud, nullptr, &error)) << error;
  return cloud;
}

// The cloud moved by `shift`, through a file: float64 or float32 PCD.
PointCloud ThroughFile(const PointCloud& cloud,
                       const Eigen::Vector3d& shift,
                       bool float64,
                       const std::string& name) {
  Isometry3d moved = Isometry3d::Identity();
  moved.translation() = shift;
  const PointCloud far = TransformCloud(moved, cloud);
  const std::string path = testing::ScratchPath(name);
  if (float64) {
    WriteFloat64Pcd(path, far);
  } else {
    std::string error;
    EXPECT_TRUE(WritePointCloud(path, far, &error)) << error;
  }
  return Read(path);
}

void ExpectSameRelativePose(const std::string& reference_file,
                            const std::string& input_file) {
  // The range filter measures from the sensor, which a moved cloud no longer
  // has at its origin: filter first, as a scan moved into a map frame is.
  const RangeFilterOptions filter;
  const PointCloud reference = FilterByRange(
      filter, Read(testing::BundledDataPath(reference_file)), nullptr);
  const PointCloud input = FilterByRange(
      filter, Read(testing::BundledDataPath(input_file)), nullptr);
  // Converged tighter than the default 1 mm step, so that the comparison
  // measures the frame, not where each run happened to stop.
  RegistrationOptions options;
  options.schedule.step_tolerance = 1e-5;
  RegistrationSummary at_origin;
  Register(options, reference, input, Isometry3d::Identity(), &at_origin);
  ASSERT_TRUE(at_origin.IsSolutionUsable()) << at_origin.message;
  struct Case {
    double c;
    bool float64;
  };
  for (const Case& k :
       {Case{1e3, false}, Case{1e3, true}, Case{1e5, true}, Case{4e6, true}}) {
    SCOPED_TRACE(std::to_string(k.c) + (k.float64 ? " float64" : " float32"));
    const Eigen::Vector3d shift(k.c, k.c, 0.0);
    Isometry3d far_from_near = Isometry3d::Identity();
    far_from_near.translation() = shift;
    RegistrationSummary far;
    // Identity guess, in the far frame: the input starts where it lies.
    Register(options,
             ThroughFile(reference, shift, k.float64, "reference.pcd"),
             ThroughFile(input, shift, k.float64, "input.pcd"),
             Isometry3d::Identity(),
             &far);
    ASSERT_TRUE(far.IsSolutionUsable()) << far.message;
    const Isometry3d back =
        far_from_near.inverse() * far.reference_from_input * far_from_near;
    // float32 at 1 km rounds the points by up to 30 um, which moves a few
    // across sampling and cell borders: another sample set, a pose a few
    // mm away (KITTI 0 -> 1: 3.4 mm, 0.016 deg). float64 keeps the points.
    const double max_m = k.float64 ? 1e-3 : 5e-3;
    const double max_deg = k.float64 ? 0.01 : 0.03;
    EXPECT_LT(TranslationErrorM(back, at_origin.reference_from_input), max_m);
    EXPECT_LT(
        RotationErrorRad(back, at_origin.reference_from_input) * kRadToDeg,
        max_deg);
  }
}

TEST(LargeCoordinates, Koide3PairGivesTheSamePoseFarFromTheOrigin) {
  ExpectSameRelativePose("koide3/251370668.pcd", "koide3/251371071.pcd");
}

TEST(LargeCoordinates, KittiPairGivesTheSamePoseFarFromTheOrigin) {
  ExpectSameRelativePose("kitti/pcd/000000.pcd", "kitti/pcd/000001.pcd");
}

}  // namespace
}  // namespace mlndt
