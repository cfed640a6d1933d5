// Runs the built mlndt_odometry on the bundled KITTI frames (folder with a
// times file, and a ROS bag written from them), checks its outputs and
// exit codes, and evaluates its TUM file with mlndt_eval against a
// reference of another rate and offset, associated by time.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "lab/eval/trajectory_io.h"
#include "mlndt/cloud/pose_io.h"
#include "tests/testing/run_tool.h"
#include "tests/testing/test_bag.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

using testing::ReadWholeFile;
using testing::RunTool;
using testing::ToolRun;
const auto& Quote = testing::ShellQuote;
namespace fs = std::filesystem;
using Json = nlohmann::json;

std::string KittiPcd() { return testing::BundledDataPath("kitti/pcd"); }

// 10 Hz stamps from 100 s, one per bundled frame.
std::string WriteTimes(const std::string& dir, size_t n) {
  std::ofstream out(dir + "/times.txt");
  out.precision(17);
  for (size_t k = 0; k < n; ++k) out << 100.0 + 0.1 * k << "\n";
  return dir + "/times.txt";
}

// The consensus chain of the bundled reference pairs (mlndt_eval chain).
std::string ReferenceChain(const std::string& dir) {
  const ToolRun chain = RunTool(
      "mlndt_eval",
      "chain " + Quote(testing::BundledDataPath("kitti/reference_pairs.json")) +
          " " + Quote(dir + "/chain.txt"));
  EXPECT_EQ(chain.exit_code, 0) << chain.err;
  return dir + "/chain.txt";
}

Trajectory ReadTum(const std::string& path) {
  Trajectory t;
  std::string error;
  EXPECT_TRUE(ReadTrajectory(path, TrajectoryFormat::TUM, &t, &error)) << error;
  return t;
}

TEST(MlndtOdometry, KittiFramesWithTimesGiveStampedTrajectoriesAndMetrics) {
  const std::string dir = testing::FreshTestDir("mlndt_odometry");
  const std::string times = WriteTimes(dir, 8);
  const ToolRun run =
      RunTool("mlndt_odometry",
              "--scans=" + Quote(KittiPcd()) + " --times=" + Quote(times) +
                  " --gt_poses=" + Quote(ReferenceChain(dir)) +
                  " --output_dir=" + Quote(dir + "/out") +
                  " --plots=false --segment_lengths=2,5");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("CONVERGENCE 8,"), std::string::npos) << run.out;
  const std::string tum_text = ReadWholeFile(dir + "/out/trajectory_tum.txt");
  EXPECT_EQ(tum_text.rfind("# time stamps: times file " + times, 0), 0u)
      << tum_text.substr(0, 200);
  const Trajectory tum = ReadTum(dir + "/out/trajectory_tum.txt");
  ASSERT_EQ(tum.size(), 8u);
  EXPECT_NEAR(tum.timestamp_s(7), 100.7, 1e-9);
  const Json summary = Json::parse(ReadWholeFile(dir + "/out/summary.json"));
  EXPECT_EQ(summary["terminations"]["CONVERGENCE"].get<int>(), 8);
  EXPECT_GT(summary["time_ms_stats"]["scan"]["median"].get<double>(), 0.0);
  EXPECT_EQ(summary["fallbacks"].get<int>(), 0);
  // Against the consensus chain: a few centimetres after alignment.
  EXPECT_LT(summary["metrics"]["ate_se3_rmse_m"].get<double>(), 0.05);
  // The segment errors under mlndt_eval's names (KittiLengthsJson).
  ASSERT_EQ(summary["metrics"]["segments"].size(), 2u);
  for (const Json& length : summary["metrics"]["segments"]) {
    EXPECT_TRUE(length.contains("translation_error_percent")) << length;
    EXPECT_TRUE(length.contains("rotation_error_deg_per_m")) << length;
  }
  const std::string csv = ReadWholeFile(dir + "/out/scans.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 9);
}

// The reference is at 20 Hz (every frame and the midpoint between frames)
// and 4 ms later than the estimate: by time, each scan pairs with its own
// reference pose; by index, scan k would meet the pose of time k / 20 s.
TEST(MlndtOdometry, EvalAssociatesItsTumFileByTimeWithAReferenceOfAnotherRate) {
  const std::string dir = testing::FreshTestDir("mlndt_odometry");
  const ToolRun run = RunTool(
      "mlndt_odometry",
      "--scans=" + Quote(KittiPcd()) + " --times=" + Quote(WriteTimes(dir, 8)) +
          " --output_dir=" + Quote(dir + "/out") + " --plots=false");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  std::vector<Isometry3d> chain;
  std::string error;
  ASSERT_TRUE(ReadKittiPoses(ReferenceChain(dir), &chain, &error)) << error;
  Trajectory reference;
  for (size_t k = 0; k < chain.size(); ++k) {
    const double t = 100.004 + 0.1 * static_cast<double>(k);
    reference.Add(t, chain[k]);
    if (k + 1 == chain.size()) break;
    Isometry3d middle = Isometry3d::Identity();
    middle.translation() =
        0.5 * (chain[k].translation() + chain[k + 1].translation());
    middle.linear() = Eigen::Quaterniond(chain[k].linear())
                          .slerp(0.5, Eigen::Quaterniond(chain[k + 1].linear()))
                          .toRotationMatrix();
    reference.Add(t + 0.05, middle);
  }
  const std::string ref = dir + "/reference_20hz.tum";
  ASSERT_TRUE(WriteTrajectory(ref, TrajectoryFormat::TUM, reference, &error));
  const auto eval = [&](const std::string& association) {
    const ToolRun e = RunTool(
        "mlndt_eval",
        "--reference=" + Quote(ref) +
            " --estimate=" + Quote(dir + "/out/trajectory_tum.txt") +
            " --association=" + association +
            " --output_json=" + Quote(dir + "/" + association + ".json"));
    EXPECT_EQ(e.exit_code, 0) << e.err;
    return Json::parse(
        ReadWholeFile(dir + "/" + association + ".json"))["estimates"][0];
  };
  const Json by_time = eval("auto");
  EXPECT_EQ(by_time["association"].get<std::string>(), "timestamp");
  EXPECT_EQ(by_time["pairs"].get<int>(), 8);
  EXPECT_LT(by_time["ate"]["rmse_m"].get<double>(), 0.05);
  const Json by_index = eval("index");
  EXPECT_GT(by_index["ate"]["rmse_m"].get<double>(), 0.3);
}

// A TUM file stamped with scan indices (no --times) says so, and mlndt_eval
// refuses to associate it by time.
TEST(MlndtOdometry, IndexStampsAreSaidAndNotAssociatedByTime) {
  const std::string dir = testing::FreshTestDir("mlndt_odometry");
  const ToolRun run =
      RunTool("mlndt_odometry",
              "--scans=" + Quote(KittiPcd()) + " --max_scans=3" +
                  " --output_dir=" + Quote(dir + "/out") + " --plots=false");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string tum = dir + "/out/trajectory_tum.txt";
  EXPECT_TRUE(TumStampsAreScanIndices(tum)) << ReadWholeFile(tum);
  const ToolRun e =
      RunTool("mlndt_eval",
              "--reference=" + Quote(tum) + " --estimate=" + Quote(tum) +
                  " --association=timestamp");
  EXPECT_EQ(e.exit_code, 1);
  EXPECT_NE(e.err.find("no time stamps"), std::string::npos) << e.err;
}

// Through a bag of the same frames (stamps 1000 + 0.1 k s), the odometry
// gives the folder's poses and the bag's stamps.
TEST(MlndtOdometry, BagGivesTheFolderPosesWithTheBagStamps) {
  MLNDT_REQUIRE_ROSBAG();
  const std::string dir = testing::FreshTestDir("mlndt_odometry");
  std::vector<std::string> scans;
  for (int i = 0; i < 4; ++i) {
    scans.push_back(KittiPcd() + "/00000" + std::to_string(i) + ".pcd");
  }
  std::string error;
  ASSERT_TRUE(
      testing::WriteTestBag(dir + "/k.bag", "/points", scans, "", &error))
      << error;
  std::ofstream(dir + "/times.txt") << "1000\n1000.1\n1000.2\n1000.3\n";
  const ToolRun folder =
      RunTool("mlndt_odometry",
              "--scans=" + Quote(KittiPcd()) + " --max_scans=4" +
                  " --times=" + Quote(dir + "/times.txt") +
                  " --output_dir=" + Quote(dir + "/folder") + " --plots=false");
  ASSERT_EQ(folder.exit_code, 2);  // --times lists 4 stamps for 8 scans.
  EXPECT_NE(folder.err.find("has 4 stamps for 8 scans"), std::string::npos)
      << folder.err;
  fs::create_directories(dir + "/pcd");
  for (const std::string& s : scans) {
    fs::copy_file(s, dir + "/pcd/" + fs::path(s).filename().string());
  }
  const ToolRun folder4 =
      RunTool("mlndt_odometry",
              "--scans=" + Quote(dir + "/pcd") +
                  " --times=" + Quote(dir + "/times.txt") +
                  " --output_dir=" + Quote(dir + "/folder") + " --plots=false");
  const ToolRun bag =
      RunTool("mlndt_odometry",
              "--bag=" + Quote(dir + "/k.bag") +
                  " --topic=/points --output_dir=" + Quote(dir + "/bag") +
                  " --plots=false");
  ASSERT_EQ(folder4.exit_code, 0) << folder4.err;
  ASSERT_EQ(bag.exit_code, 0) << bag.err;
  // The bag's stamps are integer nanoseconds: the time steps (and so the
  // predictions) differ from the text file's in the last digits only.
  std::vector<Isometry3d> from_bag, from_folder;
  ASSERT_TRUE(
      ReadKittiPoses(dir + "/bag/trajectory_kitti.txt", &from_bag, &error));
  ASSERT_TRUE(ReadKittiPoses(
      dir + "/folder/trajectory_kitti.txt", &from_folder, &error));
  ASSERT_EQ(from_bag.size(), 4u);
  ASSERT_EQ(from_folder.size(), 4u);
  for (size_t k = 0; k < 4; ++k) {
    EXPECT_TRUE(from_bag[k].isApprox(from_folder[k], 1e-9)) << "scan " << k;
  }
  const Trajectory tum = ReadTum(dir + "/bag/trajectory_tum.txt");
  ASSERT_EQ(tum.size(), 4u);
  EXPECT_NEAR(tum.timestamp_s(3), 1000.3, 1e-6);
  EXPECT_NE(
      ReadWholeFile(dir + "/bag/trajectory_tum.txt").find("header stamps"),
      std::string::npos);
}

// Misuse exits 2 before any work, names the flag and writes nothing.
TEST(MlndtOdometry, RefusesBadInputFlagsBeforeAnyWork) {
  const std::string dir = testing::FreshTestDir("mlndt_odometry");
  const std::string out = " --output_dir=" + Quote(dir + "/out");
  std::ofstream(dir + "/bad_times.txt") << "1.0\n0.5\n";
  const struct {
    std::string args;
    std::string message;
  } cases[] = {
      {"--bag=" + Quote(dir + "/x.bag") + out, "x.bag: Error opening file"},
      {"--scans=" + Quote(KittiPcd()) + " --topic=/points" + out,
       "--topic applies only with --bag"},
      {"--scans=" + Quote(KittiPcd()) + " --bag=x.bag --topic=/p" + out,
       "either --bag or a folder"},
      {"--scans=" + Quote(KittiPcd()) +
           " --times=" + Quote(dir + "/bad_times.txt") + out,
       "line 2: time 0.5 is not after the previous line's"},
      {"--scans=" + Quote(KittiPcd()) + " --gate_factor=0.5" + out,
       "gate_factor"},
      {Quote(KittiPcd()) + " --bag=x.bag" + out,
       "given as an argument and as --scans or --bag"},
  };
  for (const auto& c : cases) {
    const ToolRun run = RunTool("mlndt_odometry", c.args);
    EXPECT_EQ(run.exit_code, 2) << c.args << "\n" << run.err;
    EXPECT_NE(run.err.find(c.message), std::string::npos) << c.args << "\n"
                                                          << run.err;
  }
  EXPECT_FALSE(fs::exists(dir + "/out"));
}

}  // namespace
}  // namespace mlndt
