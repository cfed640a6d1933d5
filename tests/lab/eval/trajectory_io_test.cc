#include "lab/eval/trajectory_io.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "tests/testing/eigen_near.h"
#include "tests/testing/scratch_dir.h"

namespace mlndt {
namespace {

using testing::EigenNear;

// A fresh folder per test.
std::string TempDir() {
  const std::string dir = testing::ScratchPath("files");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir + "/";
}

std::string WriteFile(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
  return path;
}

std::string ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

::testing::AssertionResult Contains(const std::string& text,
                                    const std::string& part) {
  if (text.find(part) != std::string::npos)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "'" << text << "' does not contain '" << part << "'";
}

// Seeded random poses at TUM-like timestamps (seconds since 1970).
Trajectory RandomTrajectory(int n) {
  std::mt19937 rng(11);
  std::normal_distribution<double> normal(0.0, 5.0);
  Trajectory trajectory;
  double t = 1305031102.175304;
  for (int i = 0; i < n; ++i) {
    Isometry3d pose = Isometry3d::Identity();
    pose.linear() =
        Eigen::Quaterniond(normal(rng), normal(rng), normal(rng), normal(rng))
            .normalized()
            .toRotationMatrix();
    pose.translation() = Vector3d(normal(rng), normal(rng), normal(rng));
    trajectory.Add(t, pose);
    t += 0.0333 + 0.001 * std::abs(normal(rng));
  }
  return trajectory;
}

TEST(TrajectoryFormat, StringConversions) {
  TrajectoryFormat format;
  ASSERT_TRUE(StringToTrajectoryFormat("tum", &format));
  EXPECT_EQ(format, TrajectoryFormat::TUM);
  ASSERT_TRUE(StringToTrajectoryFormat("KITTI", &format));
  EXPECT_EQ(format, TrajectoryFormat::KITTI);
  EXPECT_FALSE(StringToTrajectoryFormat("euroc", &format));
  for (TrajectoryFormat f : {TrajectoryFormat::KITTI, TrajectoryFormat::TUM}) {
    ASSERT_TRUE(StringToTrajectoryFormat(TrajectoryFormatToString(f), &format));
    EXPECT_EQ(format, f);
  }
}

TEST(WriteTrajectory, TumRoundTripKeepsEveryNumber) {
  const std::string path = TempDir() + "trajectory.tum";
  const Trajectory written = RandomTrajectory(20);
  std::string error;
  ASSERT_TRUE(WriteTrajectory(path, TrajectoryFormat::TUM, written, &error))
      << error;
  Trajectory read;
  ASSERT_TRUE(ReadTrajectory(path, TrajectoryFormat::TUM, &read, &error))
      << error;
  ASSERT_EQ(read.size(), written.size());
  for (size_t i = 0; i < read.size(); ++i) {
    EXPECT_EQ(read.timestamp_s(i), written.timestamp_s(i)) << i;
    EXPECT_EQ(read.world_from_sensor(i).translation(),
              written.world_from_sensor(i).translation())
        << i;
    // The rotation goes through a quaternion: equal to rounding.
    EXPECT_TRUE(EigenNear(read.world_from_sensor(i).linear(),
                          written.world_from_sensor(i).linear(),
                          1e-15))
        << i;
  }
}

TEST(WriteTrajectory, KittiRoundTripIsExactWithIndexTimes) {
  const std::string path = TempDir() + "poses.txt";
  const Trajectory written = RandomTrajectory(10);
  std::string error;
  ASSERT_TRUE(WriteTrajectory(path, TrajectoryFormat::KITTI, written, &error))
      << error;
  Trajectory read;
  ASSERT_TRUE(ReadTrajectory(path, &read, &error)) << error;  // Detected.
  ASSERT_EQ(read.size(), written.size());
  for (size_t i = 0; i < read.size(); ++i) {
    EXPECT_EQ(read.timestamp_s(i), static_cast<double>(i));
    EXPECT_EQ(read.world_from_sensor(i).matrix(),
              written.world_from_sensor(i).matrix());
  }
}

TEST(WriteTrajectory, ReplacesTheFileAndLeavesNoTemporaryFile) {
  const std::string dir = TempDir();
  const std::string path = WriteFile(dir + "out.tum", "old contents\n");
  std::string error;
  ASSERT_TRUE(
      WriteTrajectory(path, TrajectoryFormat::TUM, RandomTrajectory(3), &error))
      << error;
  EXPECT_EQ(ReadFile(path).rfind("# timestamp tx ty tz qx qy qz qw\n", 0), 0u);
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    (void)entry;
    ++files;
  }
  EXPECT_EQ(files, 1);
  EXPECT_FALSE(WriteTrajectory(dir + "missing/out.tum",
                               TrajectoryFormat::TUM,
                               RandomTrajectory(3),
                               &error));
  EXPECT_TRUE(Contains(error, dir + "missing/out.tum"));
}

TEST(ReadTrajectory, TumSkipsCommentsAndNormalisesQuaternions) {
  const std::string path = WriteFile(TempDir() + "t.txt",
                                     "# ground truth\n"
                                     "\n"
                                     "1.5 1 2 3 0 0 0 1\n"
                                     "  # a comment after a pose\n"
                                     "1.75 0 0 0 0 0 0.7072 0.7072\n");
  Trajectory trajectory;
  std::string error;
  ASSERT_TRUE(ReadTrajectory(path, &trajectory, &error)) << error;
  ASSERT_EQ(trajectory.size(), 2u);
  EXPECT_EQ(trajectory.timestamp_s(0), 1.5);
  EXPECT_EQ(trajectory.world_from_sensor(0).translation(), Vector3d(1, 2, 3));
  // 90 degrees about z (|q| = 1.00014, within the tolerance).
  EXPECT_TRUE(EigenNear(trajectory.world_from_sensor(1) * Vector3d(1, 0, 0),
                        Vector3d(0, 1, 0),
                        1e-12));
}

struct MalformedCase {
  const char* name;
  const char* text;
  const char* message;  // Expected after "<path>: ".
};

TEST(ReadTrajectory, MalformedTumLinesNameFileAndLine) {
  const MalformedCase cases[] = {
      {"count", "# c\n0 0 0 0 0 0 0 1\n1 0 0 0 0 0 1\n", "line 3: expected 8"},
      {"number", "0 0 0 0 0 0 0 1\n1 0 x 0 0 0 0 1\n", "line 2: cannot parse"},
      {"nan", "0 0 0 nan 0 0 0 1\n", "line 1: non-finite"},
      {"inf", "\n\n0 0 0 0 inf 0 0 1\n", "line 3: non-finite"},
      {"norm",
       "0 0 0 0 0 0 0 1\n1 0 0 0 0 0 0 1.01\n",
       "line 2: quaternion norm 1.01"},
      {"zero_q", "0 0 0 0 0 0 0 0\n", "line 1: quaternion norm 0"},
      {"order",
       "0 0 0 0 0 0 0 1\n1 0 0 0 0 0 0 1\n# c\n1 0 0 0 0 0 0 1\n",
       "line 4: timestamp 1 is not after the one on line 2"},
      {"backwards", "5 0 0 0 0 0 0 1\n4 0 0 0 0 0 0 1\n", "line 2: timestamp"},
      {"empty", "# only a comment\n", "no poses"},
  };
  const std::string dir = TempDir();
  for (const MalformedCase& c : cases) {
    const std::string path = WriteFile(dir + c.name + ".tum", c.text);
    Trajectory trajectory;
    std::string error;
    EXPECT_FALSE(
        ReadTrajectory(path, TrajectoryFormat::TUM, &trajectory, &error))
        << c.name;
    EXPECT_TRUE(Contains(error, path + ": " + c.message)) << c.name;
    EXPECT_TRUE(trajectory.empty()) << c.name;
  }
}

TEST(ReadTrajectory, MalformedKittiLineNamesFileAndLine) {
  const std::string path = WriteFile(TempDir() + "poses.kitti",
                                     "1 0 0 0 0 1 0 0 0 0 1 0\n"
                                     "1 0 0 0 0 1 0 0 0 0 1\n");
  Trajectory trajectory;
  std::string error;
  EXPECT_FALSE(ReadTrajectory(path, &trajectory, &error));
  EXPECT_TRUE(Contains(error, path + ": line 2: expected 12 numbers"));
}

TEST(DetectTrajectoryFormat, ExtensionFirstThenFirstPoseLine) {
  const std::string dir = TempDir();
  const std::string kitti_line = "1 0 0 0 0 1 0 0 0 0 1 0\n";
  const std::string tum_line = "0 0 0 0 0 0 0 1\n";
  TrajectoryFormat format;
  std::string error;
  // The extension wins over the content (and the file need not exist).
  ASSERT_TRUE(DetectTrajectoryFormat(dir + "a.TUM", &format, &error));
  EXPECT_EQ(format, TrajectoryFormat::TUM);
  ASSERT_TRUE(DetectTrajectoryFormat(
      WriteFile(dir + "b.kitti", tum_line), &format, &error));
  EXPECT_EQ(format, TrajectoryFormat::KITTI);
  ASSERT_TRUE(DetectTrajectoryFormat(
      WriteFile(dir + "c.txt", "\n" + kitti_line), &format, &error));
  EXPECT_EQ(format, TrajectoryFormat::KITTI);
  ASSERT_TRUE(DetectTrajectoryFormat(
      WriteFile(dir + "d.txt", "# t x y z qx qy qz qw\n" + tum_line),
      &format,
      &error));
  EXPECT_EQ(format, TrajectoryFormat::TUM);
  const std::string odd = WriteFile(dir + "e.txt", "# header\n1 2 3 4 5\n");
  EXPECT_FALSE(DetectTrajectoryFormat(odd, &format, &error));
  EXPECT_TRUE(Contains(error, odd + ": line 2: cannot tell"));
  EXPECT_FALSE(DetectTrajectoryFormat(dir + "missing.txt", &format, &error));
  EXPECT_TRUE(Contains(error, dir + "missing.txt"));
}

}  // namespace
}  // namespace mlndt
