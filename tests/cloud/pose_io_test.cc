#include "mlndt/cloud/pose_io.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "tests/testing/scratch_dir.h"
#include "tests/testing/small_file_system.h"

namespace mlndt {
namespace {

std::string TempPath(const std::string& name) {
  return testing::ScratchPath(name);
}

std::string WriteFile(const std::string& name, const std::string& text) {
  const std::string path = TempPath(name);
  std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
  return path;
}

::testing::AssertionResult Contains(const std::string& text,
                                    const std::string& part) {
  if (text.find(part) != std::string::npos)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "'" << text << "' does not contain '" << part << "'";
}

double Deg(double degrees) { return degrees * M_PI / 180.0; }

// ---- KITTI poses ------------------------------------------------------------

TEST(ReadKittiPoses, RowMajorThreeByFour) {
  const std::string path = WriteFile("poses.txt",
                                     "1 0 0 0 0 1 0 0 0 0 1 0\n"
                                     "\n"
                                     "0 -1 0 1 1 0 0 2 0 0 1 3\n");
  std::vector<Eigen::Isometry3d> poses;
  std::string error;
  ASSERT_TRUE(ReadKittiPoses(path, &poses, &error)) << error;
  ASSERT_EQ(poses.size(), 2u);
  EXPECT_TRUE(poses[0].isApprox(Eigen::Isometry3d::Identity()));
  // 90 degrees about z, then translation (1, 2, 3).
  EXPECT_TRUE(poses[1].translation().isApprox(Eigen::Vector3d(1, 2, 3)));
  EXPECT_TRUE(
      (poses[1] * Eigen::Vector3d(1, 0, 0)).isApprox(Eigen::Vector3d(1, 3, 3)));
  EXPECT_TRUE(
      (poses[1] * Eigen::Vector3d(0, 1, 0)).isApprox(Eigen::Vector3d(0, 2, 3)));
}

TEST(WriteKittiPoses, RoundTripIsExact) {
  std::mt19937 rng(7);
  std::normal_distribution<double> normal(0.0, 10.0);
  std::vector<Eigen::Isometry3d> poses;
  for (int i = 0; i < 5; ++i) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() =
        Eigen::Quaterniond(normal(rng), normal(rng), normal(rng), normal(rng))
            .normalized()
            .toRotationMatrix();
    pose.translation() = Eigen::Vector3d(normal(rng), normal(rng), normal(rng));
    poses.push_back(pose);
  }
  const std::string path = TempPath("poses.txt");
  std::string error;
  ASSERT_TRUE(WriteKittiPoses(path, poses, &error)) << error;
  std::vector<Eigen::Isometry3d> read;
  ASSERT_TRUE(ReadKittiPoses(path, &read, &error)) << error;
  ASSERT_EQ(read.size(), poses.size());
  for (size_t i = 0; i < poses.size(); ++i) {
    EXPECT_EQ(read[i].matrix(), poses[i].matrix()) << "pose " << i;
  }
}

TEST(WriteKittiPoses, RefusesASymlinkAndKeepsItsTarget) {
  const std::string victim = WriteFile("victim.txt", "victim");
  const std::string link = TempPath("link.txt");
  std::remove(link.c_str());
  ASSERT_EQ(::symlink(victim.c_str(), link.c_str()), 0);
  std::string error;
  EXPECT_FALSE(WriteKittiPoses(
      link,
      std::vector<Eigen::Isometry3d>(2, Eigen::Isometry3d::Identity()),
      &error));
  EXPECT_TRUE(Contains(error, link));
  EXPECT_TRUE(Contains(error, "symbolic link"));
  struct stat status;
  ASSERT_EQ(::lstat(link.c_str(), &status), 0);
  EXPECT_TRUE(S_ISLNK(status.st_mode));
  std::ifstream in(victim);
  std::string text((std::istreambuf_iterator<char>(in)),
                   std::istreambuf_iterator<char>());
  EXPECT_EQ(text, "victim");
}

TEST(WriteKittiPoses, FullFileSystemKeepsThePreviousFile) {
  testing::SmallFileSystem fs;
  MLNDT_MOUNT_SMALL_FS_OR_SKIP(fs, 64 * 1024);
  const std::string path = fs.path() + "/trajectory.txt";
  std::string error;
  ASSERT_TRUE(WriteKittiPoses(
      path,
      std::vector<Eigen::Isometry3d>(3, Eigen::Isometry3d::Identity()),
      &error))
      << error;
  std::vector<Eigen::Isometry3d> read;
  ASSERT_TRUE(ReadKittiPoses(path, &read, &error)) << error;
  // 2000 poses of 12 numbers with 17 digits: about 500 kB.
  Eigen::Isometry3d odd = Eigen::Isometry3d::Identity();
  odd.translation() = Eigen::Vector3d(M_PI, M_E, -M_SQRT2);
  EXPECT_FALSE(
      WriteKittiPoses(path, std::vector<Eigen::Isometry3d>(2000, odd), &error));
  EXPECT_TRUE(Contains(error, path));
  EXPECT_TRUE(Contains(error, std::strerror(ENOSPC))) << error;
  ASSERT_TRUE(ReadKittiPoses(path, &read, &error)) << error;
  EXPECT_EQ(read.size(), 3u);
  size_t entries = 0;
  for (const auto& entry : std::filesystem::directory_iterator(fs.path())) {
    EXPECT_EQ(entry.path().filename(), "trajectory.txt");
    ++entries;
  }
  EXPECT_EQ(entries, 1u);
}

TEST(ReadKittiPosesErrors, MissingFile) {
  std::vector<Eigen::Isometry3d> poses;
  std::string error;
  const std::string path = TempPath("missing.txt");
  EXPECT_FALSE(ReadKittiPoses(path, &poses, &error));
  EXPECT_TRUE(Contains(error, path));
  EXPECT_TRUE(Contains(error, "cannot open file"));
}

TEST(ReadKittiPosesErrors, BadLines) {
  struct Case {
    const char* text;
    const char* keyword;
  };
  const Case cases[] = {
      {"1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0 0 0 1 0 0 0 0 1\n",
       "line 2: expected 12 numbers"},
      {"1 0 0 0 0 1 0 0 0 0 1 zero\n", "line 1: cannot parse number 'zero'"},
      {"2 0 0 0 0 2 0 0 0 0 2 0\n", "line 1: the 3x3 part is not a rotation"},
      {"-1 0 0 0 0 1 0 0 0 0 1 0\n", "not a rotation"},  // A reflection.
      // Issue 27 item 3: a number no place has (it built a map of infinite
      // cells).
      {"1 0 0 1e300 0 1 0 0 0 0 1 0\n",
       "line 1: translation (1e+300, 0, 0) m is beyond 1e+08 m"},
      {"\n\n", "no poses"},
  };
  for (const Case& c : cases) {
    const std::string path = WriteFile("bad.txt", c.text);
    std::vector<Eigen::Isometry3d> poses(3);
    std::string error;
    EXPECT_FALSE(ReadKittiPoses(path, &poses, &error)) << c.text;
    EXPECT_TRUE(poses.empty());
    EXPECT_TRUE(Contains(error, path));
    EXPECT_TRUE(Contains(error, c.keyword));
  }
}

// ---- KITTI calib.txt
// ----------------------------------------------------------

TEST(ReadKittiCalibTr, ReadsTheTrLine) {
  const std::string path = WriteFile(
      "calib.txt",
      "P0: 7.188560000000e+02 0 6.071928000000e+02 0 0 7.188560000000e+02 "
      "1.852157000000e+02 0 0 0 1 0\n"
      "Tr: 0 -1 0 -0.01 0 0 -1 -0.05 1 0 0 -0.29\n");
  Eigen::Isometry3d cam0_from_velo;
  std::string error;
  ASSERT_TRUE(ReadKittiCalibTr(path, &cam0_from_velo, &error)) << error;
  // Velodyne forward (x) is camera forward (z).
  EXPECT_TRUE(
      cam0_from_velo.linear().col(0).isApprox(Eigen::Vector3d(0, 0, 1)));
  EXPECT_TRUE(cam0_from_velo.translation().isApprox(
      Eigen::Vector3d(-0.01, -0.05, -0.29)));
}

TEST(ReadKittiCalibTrErrors, MissingOrShortTrLine) {
  Eigen::Isometry3d cam0_from_velo;
  std::string error;
  const std::string no_tr =
      WriteFile("no_tr.txt", "P0: 1 0 0 0 0 1 0 0 0 0 1 0\n");
  EXPECT_FALSE(ReadKittiCalibTr(no_tr, &cam0_from_velo, &error));
  EXPECT_TRUE(Contains(error, no_tr));
  EXPECT_TRUE(Contains(error, "no 'Tr:' line"));

  const std::string short_tr =
      WriteFile("short_tr.txt", "P0: 1\nTr: 1 0 0 0 0 1 0 0 0 0 1\n");
  EXPECT_FALSE(ReadKittiCalibTr(short_tr, &cam0_from_velo, &error));
  EXPECT_TRUE(Contains(error, short_tr));
  EXPECT_TRUE(
      Contains(error, "line 2: the Tr: line has 11 numbers, expected 12"));

  EXPECT_FALSE(
      ReadKittiCalibTr(TempPath("missing.txt"), &cam0_from_velo, &error));
  EXPECT_TRUE(Contains(error, "cannot open file"));
}

// ---- 3DTK -------------------------------------------------------------------

// Our own statement of the axis mapping (io.h): x_r = z/100, y_r = -x/100,
// z_r = y/100.
Eigen::Vector3d MapToMetric(const Eigen::Vector3d& p) {
  return Eigen::Vector3d(p.z() / 100, -p.x() / 100, p.y() / 100);
}

// 3DTK's EulerToMatrix4 (include/slam6d/globals.icc), written out
// independently: a column-major 4x4 array applied as in Point::transform.
Eigen::Vector3d Apply3dtkPose(const double position[3],
                              const double theta_deg[3],
                              const Eigen::Vector3d& p) {
  const double sx = std::sin(Deg(theta_deg[0])),
               cx = std::cos(Deg(theta_deg[0]));
  const double sy = std::sin(Deg(theta_deg[1])),
               cy = std::cos(Deg(theta_deg[1]));
  const double sz = std::sin(Deg(theta_deg[2])),
               cz = std::cos(Deg(theta_deg[2]));
  double m[16];
  m[0] = cy * cz;
  m[1] = sx * sy * cz + cx * sz;
  m[2] = -cx * sy * cz + sx * sz;
  m[3] = 0.0;
  m[4] = -cy * sz;
  m[5] = -sx * sy * sz + cx * cz;
  m[6] = cx * sy * sz + sx * cz;
  m[7] = 0.0;
  m[8] = sy;
  m[9] = -sx * cy;
  m[10] = cx * cy;
  m[11] = 0.0;
  m[12] = position[0];
  m[13] = position[1];
  m[14] = position[2];
  m[15] = 1;
  return Eigen::Vector3d(p.x() * m[0] + p.y() * m[4] + p.z() * m[8] + m[12],
                         p.x() * m[1] + p.y() * m[5] + p.z() * m[9] + m[13],
                         p.x() * m[2] + p.y() * m[6] + p.z() * m[10] + m[14]);
}

TEST(Convert3dtk, PointMapping) {
  EXPECT_TRUE(Convert3dtkPoint(Eigen::Vector3d(100, 200, 300))
                  .isApprox(Eigen::Vector3d(3, -1, 2)));
  // Right (+x_l) becomes -y_r, up (+y_l) becomes +z_r, forward (+z_l) +x_r.
  EXPECT_TRUE(Convert3dtkPoint(Eigen::Vector3d(100, 0, 0))
                  .isApprox(Eigen::Vector3d(0, -1, 0)));
  EXPECT_TRUE(Convert3dtkPoint(Eigen::Vector3d(0, 100, 0))
                  .isApprox(Eigen::Vector3d(0, 0, 1)));
  EXPECT_TRUE(Convert3dtkPoint(Eigen::Vector3d(0, 0, 100))
                  .isApprox(Eigen::Vector3d(1, 0, 0)));
}

TEST(Convert3dtk, ZeroPoseIsIdentity) {
  EXPECT_TRUE(Convert3dtkPose(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero())
                  .isApprox(Eigen::Isometry3d::Identity()));
}

TEST(Convert3dtk, RotationAboutUpAxisIsNegativeYaw) {
  // +30 deg about 3DTK's y (up) turns forward towards the right: -30 deg yaw.
  const Eigen::Isometry3d pose =
      Convert3dtkPose(Eigen::Vector3d(0, 0, 150), Eigen::Vector3d(0, 30, 0));
  EXPECT_TRUE(pose.linear().isApprox(
      Eigen::AngleAxisd(Deg(-30), Eigen::Vector3d::UnitZ())
          .toRotationMatrix()));
  EXPECT_TRUE(pose.translation().isApprox(Eigen::Vector3d(1.5, 0, 0)));
}

TEST(Convert3dtk, PoseCommutesWithPointMapping) {
  // Transforming in the 3DTK frame and then mapping equals mapping and then
  // applying the converted pose.
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> angle(-180, 180), length(-500, 500);
  for (int trial = 0; trial < 20; ++trial) {
    const double position[3] = {length(rng), length(rng), length(rng)};
    const double theta[3] = {angle(rng), angle(rng), angle(rng)};
    const Eigen::Isometry3d world_from_scan =
        Convert3dtkPose(Eigen::Vector3d(position[0], position[1], position[2]),
                        Eigen::Vector3d(theta[0], theta[1], theta[2]));
    EXPECT_NEAR(world_from_scan.linear().determinant(), 1.0, 1e-12);
    EXPECT_TRUE(
        (world_from_scan.linear().transpose() * world_from_scan.linear())
            .isApprox(Eigen::Matrix3d::Identity(), 1e-12));
    for (int k = 0; k < 5; ++k) {
      const Eigen::Vector3d point_3dtk(length(rng), length(rng), length(rng));
      const Eigen::Vector3d expected =
          MapToMetric(Apply3dtkPose(position, theta, point_3dtk));
      const Eigen::Vector3d actual = world_from_scan * MapToMetric(point_3dtk);
      EXPECT_LT((expected - actual).norm(), 1e-12) << "trial " << trial;
    }
  }
}

TEST(Read3dtkPose, ReadsPositionAndDegrees) {
  const std::string path = WriteFile("scan001.pose",
                                     "-3.10605 -7.50803 156.917\n"
                                     "1.35694 -0.852409 -0.56224\n"
                                     "\n");
  Eigen::Isometry3d world_from_scan;
  std::string error;
  ASSERT_TRUE(Read3dtkPose(path, &world_from_scan, &error)) << error;
  EXPECT_TRUE(world_from_scan.isApprox(
      Convert3dtkPose(Eigen::Vector3d(-3.10605, -7.50803, 156.917),
                      Eigen::Vector3d(1.35694, -0.852409, -0.56224))));
  EXPECT_TRUE(world_from_scan.translation().isApprox(
      Eigen::Vector3d(1.56917, 0.0310605, -0.0750803)));
}

TEST(Read3dtkPose, NegativeZeroIdentity) {
  const std::string path = WriteFile("scan000.pose", "0 0 0\n-0 0 -0\n\n");
  Eigen::Isometry3d world_from_scan;
  std::string error;
  ASSERT_TRUE(Read3dtkPose(path, &world_from_scan, &error)) << error;
  EXPECT_TRUE(world_from_scan.isApprox(Eigen::Isometry3d::Identity()));
}

TEST(Read3dtkPoseErrors, WrongCountOrNotNumbers) {
  struct Case {
    const char* text;
    const char* keyword;
  };
  const Case cases[] = {
      {"0 0 0\n0 0\n", "expected 6 numbers"},
      {"0 0 0\n0 0 0\n1\n", "expected 6 numbers"},
      {"0 0 0\na b c\n", "cannot parse number 'a'"},
      {"", "expected 6 numbers"},
  };
  for (const Case& c : cases) {
    const std::string path = WriteFile("bad.pose", c.text);
    Eigen::Isometry3d world_from_scan;
    std::string error;
    EXPECT_FALSE(Read3dtkPose(path, &world_from_scan, &error)) << c.text;
    EXPECT_TRUE(Contains(error, path));
    EXPECT_TRUE(Contains(error, c.keyword));
  }
  Eigen::Isometry3d world_from_scan;
  std::string error;
  EXPECT_FALSE(
      Read3dtkPose(TempPath("missing.pose"), &world_from_scan, &error));
  EXPECT_TRUE(Contains(error, "cannot open file"));
}

}  // namespace
}  // namespace mlndt
