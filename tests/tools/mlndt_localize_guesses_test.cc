// mlndt_localize --guesses=FILE: every scan of the bundled KITTI frames
// starts from its own guess (the chained reference moved by 0.5 m and 5
// degrees), matched by stamp; the guesses file's bad inputs are refused
// with exit 2 before anything is written.

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "mlndt/cloud/pose_io.h"
#include "mlndt/common/pose.h"
#include "tests/testing/run_tool.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

using testing::ToolRun;
const auto& Quote = testing::ShellQuote;
namespace fs = std::filesystem;

std::string KittiPcd() { return testing::BundledDataPath("kitti/pcd"); }

// The chained reference poses (mlndt_eval chain) and the map built from
// them (mlndt_map), in `dir`; the poses read into *poses.
std::string BuildKittiMap(const std::string& dir,
                          std::vector<Isometry3d>* poses) {
  const std::string chained = dir + "/chained.txt";
  const std::string map = dir + "/kitti.mlndt";
  const ToolRun chain = testing::RunTool(
      "mlndt_eval",
      "chain " + Quote(testing::BundledDataPath("kitti/reference_pairs.json")) +
          " " + Quote(chained));
  EXPECT_EQ(chain.exit_code, 0) << chain.err;
  const ToolRun built = testing::RunTool(
      "mlndt_map",
      "--scans=" + Quote(KittiPcd()) + " --poses=" + Quote(chained) +
          " --min_range_m=3 --max_range_m=80 --voxel_size=0.2 --output=" +
          Quote(map));
  EXPECT_EQ(built.exit_code, 0) << built.err;
  std::string error;
  EXPECT_TRUE(ReadKittiPoses(chained, poses, &error)) << error;
  return map;
}

// A TUM file of `poses` stamped `first_stamp`, +1, +2, ...
void WriteTum(const std::string& path,
              const std::vector<Isometry3d>& poses,
              double first_stamp) {
  std::ofstream out(path);
  for (size_t k = 0; k < poses.size(); ++k) {
    const Eigen::Quaterniond q(poses[k].linear());
    const Eigen::Vector3d t = poses[k].translation();
    char line[256];
    std::snprintf(line,
                  sizeof(line),
                  "%.6f %.9f %.9f %.9f %.9f %.9f %.9f %.9f\n",
                  first_stamp + static_cast<double>(k),
                  t.x(),
                  t.y(),
                  t.z(),
                  q.x(),
                  q.y(),
                  q.z(),
                  q.w());
    out << line;
  }
}

// Each reference pose moved by 0.5 m and 5 degrees (a different direction
// per scan).
std::vector<Isometry3d> OffsetGuesses(const std::vector<Isometry3d>& poses) {
  std::vector<Isometry3d> guesses;
  for (size_t k = 0; k < poses.size(); ++k) {
    const double sign = k % 2 == 0 ? 1.0 : -1.0;
    guesses.push_back(poses[k] *
                      PoseVectorToIsometry(PoseVectorFromDegrees(
                          0.3 * sign, 0.4, 0.0, 0.0, 0.0, 5.0 * sign)));
  }
  return guesses;
}

TEST(MlndtLocalizeGuesses, EveryScanFromItsOwnGuess) {
  const std::string dir = testing::FreshTestDir("mlndt_localize_guesses");
  std::vector<Isometry3d> reference;
  const std::string map = BuildKittiMap(dir, &reference);
  ASSERT_EQ(reference.size(), 8u);
  WriteTum(dir + "/guesses.tum", OffsetGuesses(reference), 0.0);
  const ToolRun run =
      testing::RunTool("mlndt_localize",
                       "--map=" + Quote(map) + " --scans=" + Quote(KittiPcd()) +
                           " --guesses=" + Quote(dir + "/guesses.tum") +
                           " --guess_translation_m=1 --guess_rotation_deg=10"
                           " --plots=false --output_dir=" +
                           Quote(dir + "/out"));
  ASSERT_EQ(run.exit_code, 0) << run.err << run.out;
  std::vector<Isometry3d> estimate;
  std::string error;
  ASSERT_TRUE(
      ReadKittiPoses(dir + "/out/trajectory_kitti.txt", &estimate, &error))
      << error;
  ASSERT_EQ(estimate.size(), reference.size());
  for (size_t k = 0; k < estimate.size(); ++k) {
    EXPECT_LT(TranslationErrorM(reference[k], estimate[k]), 0.2) << k;
    EXPECT_LT(RotationErrorRad(reference[k], estimate[k]) * kRadToDeg, 1.0)
        << k;
  }
}

// A scan without a guess, stamps that match no scan, a KITTI file and
// --guesses beside --initial_guess: exit 2, nothing written.
TEST(MlndtLocalizeGuesses, BadGuessesExitTwoAndWriteNothing) {
  const std::string dir = testing::FreshTestDir("mlndt_localize_guesses_bad");
  std::vector<Isometry3d> reference;
  const std::string map = BuildKittiMap(dir, &reference);
  ASSERT_EQ(reference.size(), 8u);
  const std::vector<Isometry3d> seven(reference.begin(), reference.end() - 1);
  WriteTum(dir + "/seven.tum", seven, 0.0);
  WriteTum(dir + "/shifted.tum", reference, 0.5);
  WriteTum(dir + "/good.tum", reference, 0.0);
  struct Case {
    std::string args;
    std::string message;
  };
  const std::vector<Case> cases = {
      {"--guesses=" + Quote(dir + "/seven.tum"), "scan 7"},
      {"--guesses=" + Quote(dir + "/shifted.tum"), "scan 0"},
      {"--guesses=" + Quote(dir + "/chained.txt"), "--guesses"},
      {"--guesses=" + Quote(dir + "/good.tum") + " --initial_guess=1,0,0,0,0,0",
       "--initial_guess"},
      {"--guesses=" + Quote(dir + "/good.tum") +
           " --guesses_max_time_difference_s=-1",
       "guesses_max_time_difference_s"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.args);
    const std::string out = dir + "/out";
    const ToolRun run = testing::RunTool(
        "mlndt_localize",
        "--map=" + Quote(map) + " --scans=" + Quote(KittiPcd()) + " " + c.args +
            " --plots=false --output_dir=" + Quote(out));
    EXPECT_EQ(run.exit_code, 2) << run.err;
    EXPECT_NE(run.err.find(c.message), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(out));
  }
}

}  // namespace
}  // namespace mlndt
