// Runs the built mlndt_posegraph binary (tests/testing/test_data.h ToolPath)
// on the bundled KITTI frames 0-7 and checks its outputs and exit codes.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "mlndt/cloud/pose_io.h"
#include "tests/testing/run_tool.h"
#include "tests/testing/scratch_dir.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

using testing::ToolRun;
const auto& Quote = testing::ShellQuote;
const auto& ReadFile = testing::ReadWholeFile;

// A fresh folder per test (ctest may run tests in parallel).
std::string TempDir(const std::string& name) {
  const std::string dir = testing::ScratchPath(name);
  std::system(("rm -rf " + Quote(dir) + " && mkdir -p " + Quote(dir)).c_str());
  return dir;
}

ToolRun RunPosegraph(const std::string& args, const std::string& /*dir*/) {
  return testing::RunTool("mlndt_posegraph", args);
}

// The number after `"key": ` in `json`; NaN when absent.
double NumberAfter(const std::string& json,
                   const std::string& key,
                   size_t from = 0) {
  const std::string pattern = "\"" + key + "\": ";
  const size_t at = json.find(pattern, from);
  if (at == std::string::npos) return std::nan("");
  const char* begin = json.c_str() + at + pattern.size();
  char* stop = nullptr;
  const double value = std::strtod(begin, &stop);
  return stop == begin ? std::nan("") : value;
}

int CountLines(const std::string& text) {
  std::istringstream stream(text);
  std::string line;
  int lines = 0;
  while (std::getline(stream, line)) lines += !line.empty();
  return lines;
}

TEST(MlndtPosegraph, JointIsNotWorseThanChainedOnKittiFrames0To7) {
  const std::string dir = TempDir("kitti");
  const std::string json_path = dir + "/result.json";
  const ToolRun run =
      RunPosegraph("--scans=" + Quote(testing::BundledDataPath("kitti/pcd")) +
                       " --gt_poses=" +
                       Quote(testing::BundledDataPath("kitti/poses_velo.txt")) +
                       " --num_threads=2 --output_dir=" + Quote(dir) +
                       " --output_json=" + Quote(json_path),
                   dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;

  // Both trajectories: 8 KITTI lines that read back as poses, scan 0 = world.
  for (const std::string name :
       {"trajectory_chained.txt", "trajectory_joint.txt"}) {
    SCOPED_TRACE(name);
    EXPECT_EQ(CountLines(ReadFile(dir + "/" + name)), 8);
    std::vector<Eigen::Isometry3d> poses;
    std::string error;
    ASSERT_TRUE(ReadKittiPoses(dir + "/" + name, &poses, &error)) << error;
    ASSERT_EQ(poses.size(), 8u);
    EXPECT_TRUE(poses[0].isApprox(Eigen::Isometry3d::Identity(), 1e-12));
    // The car drives ~0.86 m per frame along x.
    EXPECT_GT(poses[7].translation().x(), 4.0);
  }

  // The same JSON on stdout and in the file, with the four metrics.
  const std::string json = ReadFile(json_path);
  EXPECT_EQ(json, run.out);
  EXPECT_EQ(NumberAfter(json, "schema_version"), 2.0) << json;
  EXPECT_GT(NumberAfter(json, "total"), NumberAfter(json, "joint")) << json;
  for (const std::string key :
       {"ate_chained_m", "ate_joint_m", "rpe_chained", "rpe_joint"}) {
    EXPECT_NE(json.find("\"" + key + "\": "), std::string::npos)
        << key << " in " << json;
  }
  const double ate_chained = NumberAfter(json, "ate_chained_m");
  const double ate_joint = NumberAfter(json, "ate_joint_m");
  ASSERT_TRUE(std::isfinite(ate_chained)) << json;
  ASSERT_TRUE(std::isfinite(ate_joint)) << json;
  EXPECT_LE(ate_joint, ate_chained) << json;
  // The scans fit ~0.8 x the ground-truth translation, so even a perfect
  // registration drifts ~0.17 m per frame from it: ATE over 8 frames ~0.6 m.
  EXPECT_LT(ate_chained, 1.5) << json;
  const size_t rpe_joint = json.find("\"rpe_joint\": ");
  const double rpe_translation = NumberAfter(json, "translation_m", rpe_joint);
  EXPECT_GT(rpe_translation, 0.0) << json;
  EXPECT_LT(rpe_translation, 0.3) << json;
  EXPECT_LT(NumberAfter(json, "rotation_deg", rpe_joint), 1.0) << json;
  // The joint solve lowered its own objective below its value at the
  // chained poses (a check free of the ground truth).
  EXPECT_LE(NumberAfter(json, "joint_final_cost"),
            NumberAfter(json, "joint_cost_at_chained"))
      << json;
  EXPECT_EQ(NumberAfter(json, "chained_failures"), 0.0) << json;
}

TEST(MlndtPosegraph, WithoutGroundTruthThereAreNoMetrics) {
  const std::string dir = TempDir("no_gt");
  // Three scans keep it quick (in their own folder: stderr.txt would be
  // read as an XYZ cloud).
  const std::string scans = dir + "/scans";
  std::system(("mkdir -p " + Quote(scans)).c_str());
  for (const char* name : {"000000.pcd", "000001.pcd", "000002.pcd"}) {
    std::system(
        ("cp " +
         Quote(testing::BundledDataPath(std::string("kitti/pcd/") + name)) +
         " " + Quote(scans) + "/")
            .c_str());
  }
  const ToolRun run =
      RunPosegraph("--scans=" + Quote(scans) + " --neighbors=1", dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(NumberAfter(run.out, "scans"), 3.0) << run.out;
  EXPECT_EQ(run.out.find("ate_"), std::string::npos) << run.out;
  EXPECT_EQ(run.out.find("rpe_"), std::string::npos) << run.out;
}

// From the odometry (KITTI's own poses) with its factors and a loop-style
// extra pair: the JSON names the start, the factors and the pair, and
// trajectory_odometry.txt holds the odometry moved to scan 0.
TEST(MlndtPosegraph, OdometryFactorsExtraPairsAndOdometryStart) {
  const std::string dir = TempDir("odometry");
  const std::string poses = testing::BundledDataPath("kitti/poses_velo.txt");
  const ToolRun run = RunPosegraph(
      "--scans=" + Quote(testing::BundledDataPath("kitti/pcd")) +
          " --gt_poses=" + Quote(poses) + " --odometry_poses=" + Quote(poses) +
          " --init=odometry --odometry_noise_sigma_m=0.1 "
          "--odometry_noise_sigma_deg=1"
          " --neighbors=1 --pairs=0:7 --information_scale=1 --output_dir=" +
          Quote(dir),
      dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("\"init\": \"odometry\""), std::string::npos)
      << run.out;
  EXPECT_EQ(NumberAfter(run.out, "odometry_factors"), 7.0) << run.out;
  EXPECT_EQ(NumberAfter(run.out, "extra_pairs"), 1.0) << run.out;
  EXPECT_EQ(NumberAfter(run.out, "directed_pairs"), 16.0) << run.out;
  EXPECT_EQ(NumberAfter(run.out, "odometry_sigma_m"), 0.1) << run.out;
  EXPECT_EQ(NumberAfter(run.out, "information_scale"), 1.0) << run.out;
  // The start is the truth itself: its ATE is zero, and the joint solve,
  // pulled by the scans (which fit ~0.8x KITTI's translation), leaves it.
  EXPECT_LT(NumberAfter(run.out, "ate_odometry_m"), 1e-6) << run.out;
  EXPECT_GT(NumberAfter(run.out, "ate_joint_m"), 0.05) << run.out;
  EXPECT_LE(NumberAfter(run.out, "joint_final_cost"),
            NumberAfter(run.out, "joint_cost_at_odometry"))
      << run.out;
  EXPECT_EQ(CountLines(ReadFile(dir + "/trajectory_odometry.txt")), 8);
  EXPECT_EQ(CountLines(ReadFile(dir + "/trajectory_joint.txt")), 8);
}

// Issue 27: a chain whose registrations are not usable (forced here by an
// inlier threshold no fit reaches) still writes its files, but the
// trajectories are not to be used: exit 1, saying so (was exit 0).
TEST(MlndtPosegraph, UnusableChainedRegistrationsExitOne) {
  const std::string dir = TempDir("unusable");
  const std::string scans = dir + "/scans";
  std::system(("mkdir -p " + Quote(scans)).c_str());
  for (const char* name : {"000000.pcd", "000001.pcd", "000002.pcd"}) {
    std::system(
        ("cp " +
         Quote(testing::BundledDataPath(std::string("kitti/pcd/") + name)) +
         " " + Quote(scans) + "/")
            .c_str());
  }
  const ToolRun run = RunPosegraph(
      "--scans=" + Quote(scans) +
          " --neighbors=1 --min_inlier_fraction=1 --yaw_seeds_deg= "
          "--output_dir=" +
          Quote(dir + "/out"),
      dir);
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_NE(run.err.find("2 chained registration(s) were not usable"),
            std::string::npos)
      << run.err;
  EXPECT_EQ(NumberAfter(run.out, "chained_failures"), 2.0) << run.out;
  EXPECT_EQ(CountLines(ReadFile(dir + "/out/trajectory_chained.txt")), 3);
}

TEST(MlndtPosegraph, BadFlagsExitWithTwo) {
  const std::string dir = TempDir("bad_flags");
  const std::string scans =
      " --scans=" + Quote(testing::BundledDataPath("kitti/pcd"));
  // Ground truth with 2 poses for 8 scans.
  const std::string short_gt = dir + "/short_gt.txt";
  std::system(("head -n 2 " +
               Quote(testing::BundledDataPath("kitti/poses_velo.txt")) + " > " +
               Quote(short_gt))
                  .c_str());
  // A folder with a single scan.
  const std::string one_scan = dir + "/one_scan";
  std::system(("mkdir -p " + Quote(one_scan) + " && cp " +
               Quote(testing::BundledDataPath("kitti/pcd/000000.pcd")) + " " +
               Quote(one_scan))
                  .c_str());
  for (const std::string& args : {
           std::string(""),                      // No --scans.
           scans + " --neighbors=0",             // Not >= 1.
           scans + " --joint_layers=3",          // 1 or 2.
           scans + " --joint_max_iterations=0",  // Not >= 1.
           scans + " --backend=nonsense",        // Registration flag.
           scans + " --method=ndt",              // Not ML-NDT.
           scans + " --loss_scale=-1",           // Invalid option.
           scans + " --poses_are_camera",        // Without --calib.
           scans + " --gt_poses=" +
               Quote(dir + "/missing.txt"),           // Unreadable file.
           scans + " --gt_poses=" + Quote(short_gt),  // Too few poses.
           " --scans=" + Quote(dir + "/missing"),     // No folder.
           " --scans=" + Quote(one_scan),             // Fewer than 2 scans.
           scans + " --output_dir=" +
               Quote(short_gt + "/out"),  // A file as the folder's parent.
           scans + " --pairs=0-7",        // Not i:j.
           scans + " --pairs=0:8",        // Scans are 0..7.
           scans + " --pairs=3:3",        // Not a pair.
           scans + " --init=odometry",    // Without --odometry_poses.
           scans + " --init=gt",          // chained or odometry.
           scans + " --information_scale=0",
           scans + " --odometry_poses=" + Quote(short_gt),  // Too few poses.
           scans + " --odometry_noise_sigma_m=0 --odometry_poses=" +
               Quote(testing::BundledDataPath("kitti/poses_velo.txt")),
       }) {
    SCOPED_TRACE(args);
    const ToolRun run = RunPosegraph(args, dir);
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_NE(run.err.find("mlndt_posegraph"), std::string::npos) << run.err;
    EXPECT_TRUE(run.out.empty()) << run.out;
  }
}

}  // namespace
}  // namespace mlndt
