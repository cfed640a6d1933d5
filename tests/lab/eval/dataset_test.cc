#include "lab/eval/dataset.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "mlndt/cloud/pose_io.h"
#include "mlndt/common/pose.h"
#include "tests/testing/eigen_near.h"
#include "tests/testing/scratch_dir.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

using testing::EigenNear;

std::string FileName(const std::string& path) {
  return std::filesystem::path(path).filename().string();
}

TEST(ListScanFiles, KittiFolderHasEightScansInOrder) {
  std::vector<std::string> paths;
  std::string error;
  ASSERT_TRUE(
      ListScanFiles(testing::BundledDataPath("kitti/pcd"), {}, &paths, &error))
      << error;
  ASSERT_EQ(paths.size(), 8u);
  for (size_t i = 0; i < paths.size(); ++i) {
    EXPECT_EQ(FileName(paths[i]), "00000" + std::to_string(i) + ".pcd");
    EXPECT_TRUE(std::filesystem::is_regular_file(paths[i]));
  }
}

TEST(ListScanFiles, SortsByNameSkipsOtherFilesAndExcludes) {
  const std::string dir = testing::ScratchPath("list_scan_files");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir + "/sub.pcd");  // A folder.
  for (const char* name : {"b.ply", "a.pcd", "poses.txt", "notes.md", "c.bin"})
    std::ofstream(dir + "/" + name) << "x";
  std::vector<std::string> paths;
  std::string error;
  ASSERT_TRUE(ListScanFiles(dir, {"", dir + "/poses.txt"}, &paths, &error))
      << error;
  std::vector<std::string> names;
  for (const std::string& p : paths) names.push_back(FileName(p));
  EXPECT_EQ(names, (std::vector<std::string>{"a.pcd", "b.ply", "c.bin"}));
  // Without the exclusion too: a .txt file beside binary scans is not a
  // scan (issue 41 item 11).
  ASSERT_TRUE(ListScanFiles(dir, {}, &paths, &error)) << error;
  EXPECT_EQ(paths.size(), 3u);
}

// In a folder of text clouds, the .txt files whose first line is not a
// point (stamps, KITTI's calib.txt) are not scans (issue 41 item 11).
TEST(ListScanFiles, TextCloudFolderLeavesOutStampsAndCalibration) {
  const std::string dir = testing::ScratchPath("list_text_scans");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/000.txt") << "# x y z\n1 2 3\n4 5 6\n";
  std::ofstream(dir + "/001.txt") << "\n1.5,2,3,0.7\n";
  std::ofstream(dir + "/002.xyz") << "1 2 3\n";
  std::ofstream(dir + "/stamps.txt") << "0\n0.1\n0.2\n";
  std::ofstream(dir + "/calib.txt") << "P0: 7.1e+02 0 6.0e+02 0\nTr: 1 0 0 0\n";
  std::ofstream(dir + "/two.txt") << "1 2\n";
  std::vector<std::string> paths;
  std::string error;
  ASSERT_TRUE(ListScanFiles(dir, {}, &paths, &error)) << error;
  std::vector<std::string> names;
  for (const std::string& p : paths) names.push_back(FileName(p));
  EXPECT_EQ(names, (std::vector<std::string>{"000.txt", "001.txt", "002.xyz"}));
}

TEST(ListScanFiles, MissingOrEmptyFolderIsAnError) {
  std::vector<std::string> paths;
  std::string error;
  EXPECT_FALSE(ListScanFiles("/nonexistent/scans", {}, &paths, &error));
  EXPECT_NE(error.find("/nonexistent/scans: not a folder"), std::string::npos);
  const std::string dir = testing::ScratchPath("empty");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  EXPECT_FALSE(ListScanFiles(dir, {}, &paths, &error));
  EXPECT_NE(error.find("no point-cloud files"), std::string::npos) << error;
}

TEST(CameraToVelodynePoses, ConjugatesWithTr) {
  const Isometry3d tr =
      PoseVectorToIsometry(PoseVectorFromDegrees(0.1, -0.2, 0.3, -90, 0, -90));
  const Isometry3d p =
      PoseVectorToIsometry(PoseVectorFromDegrees(1, 2, 3, 4, 5, 6));
  const std::vector<Isometry3d> v =
      CameraToVelodynePoses({Isometry3d::Identity(), p}, tr);
  ASSERT_EQ(v.size(), 2u);
  EXPECT_TRUE(v[0].isApprox(Isometry3d::Identity(), 1e-12));
  // V maps a Velodyne point x as Tr^-1 P Tr x.
  const Vector3d x(4, -5, 6);
  EXPECT_TRUE(EigenNear(v[1] * x, tr.inverse() * (p * (tr * x)), 1e-12));
}

TEST(ReadSequencePoses, KittiCameraPosesBecomeTheBundledVelodynePoses) {
  std::vector<Isometry3d> converted, velo;
  std::string error;
  ASSERT_TRUE(
      ReadSequencePoses(testing::BundledDataPath("kitti/poses_cam0.txt"),
                        testing::BundledDataPath("kitti/calib.txt"),
                        &converted,
                        &error))
      << error;
  ASSERT_TRUE(ReadSequencePoses(
      testing::BundledDataPath("kitti/poses_velo.txt"), "", &velo, &error))
      << error;
  ASSERT_EQ(converted.size(), 8u);
  ASSERT_EQ(velo.size(), 8u);
  for (size_t i = 0; i < velo.size(); ++i) {
    EXPECT_TRUE(EigenNear(converted[i].matrix(), velo[i].matrix(), 2e-6)) << i;
  }
  // The README's example: frames 0 -> 1 move about (0.859, 0.047, 0.022) m.
  EXPECT_TRUE(EigenNear((converted[0].inverse() * converted[1]).translation(),
                        Vector3d(0.859, 0.047, 0.022),
                        1e-3));
  EXPECT_FALSE(
      ReadSequencePoses(testing::BundledDataPath("kitti/poses_cam0.txt"),
                        "/nonexistent/calib.txt",
                        &converted,
                        &error));
  EXPECT_NE(error.find("/nonexistent/calib.txt"), std::string::npos) << error;
}

}  // namespace
}  // namespace mlndt
