// No output of a tool may overwrite one of its inputs (tools/cli/
// input_files.h, issue 27 item 10): refused with exit 2, naming the flag and
// the input, before any work, the input left byte for byte as it was.

#include "tools/cli/input_files.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/testing/run_tool.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

namespace fs = std::filesystem;
using testing::ReadWholeFile;
using testing::ToolRun;
const auto& Quote = testing::ShellQuote;

std::string TestDir() { return testing::FreshTestDir("input_files"); }

// A copy of a bundled file in `dir`.
std::string CopyOf(const std::string& bundled, const std::string& dir) {
  const std::string path = dir + "/" + fs::path(bundled).filename().string();
  fs::copy_file(testing::BundledDataPath(bundled), path);
  return path;
}

// `args` is refused with exit 2 naming `flag` as an input's overwrite, and
// every file of `inputs` keeps its bytes.
void ExpectRefused(const std::string& tool,
                   const std::string& args,
                   const std::string& flag,
                   const std::vector<std::string>& inputs) {
  std::vector<std::string> before;
  for (const std::string& input : inputs) {
    before.push_back(ReadWholeFile(input));
  }
  const ToolRun run = testing::RunTool(tool, args);
  EXPECT_EQ(run.exit_code, 2) << tool << " " << args << "\n" << run.err;
  EXPECT_NE(run.err.find("--" + flag + "="), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("refusing to overwrite an input of this run"),
            std::string::npos)
      << run.err;
  for (size_t k = 0; k < inputs.size(); ++k) {
    EXPECT_EQ(ReadWholeFile(inputs[k]), before[k]) << inputs[k];
  }
}

TEST(OutputIsNotAnInput, MlndtAlignPositionalScansAndFlags) {
  const std::string dir = TestDir();
  const std::string r = CopyOf("koide3/251370668.pcd", dir);
  const std::string i = CopyOf("koide3/251371071.pcd", dir);
  const std::string pair = Quote(r) + " " + Quote(i);
  ExpectRefused("mlndt_align",
                pair + " --output_json=" + Quote(r),
                "output_json",
                {r, i});
  ExpectRefused("mlndt_align",
                pair + " --output_cloud=" + Quote(i),
                "output_cloud",
                {r, i});
  // The same file by another name: "./", a symbolic link's target, a hard
  // link.
  ExpectRefused("mlndt_align",
                "--reference=" + Quote(r) + " --input=" + Quote(i) +
                    " --output_json=" +
                    Quote(dir + "/./" + fs::path(r).filename().string()),
                "output_json",
                {r, i});
  ASSERT_EQ(::link(i.c_str(), (dir + "/hard.json").c_str()), 0);
  ExpectRefused("mlndt_align",
                pair + " --output_json=" + Quote(dir + "/hard.json"),
                "output_json",
                {r, i});
  const std::string expected = CopyOf("koide3/T_target_source.txt", dir);
  ExpectRefused("mlndt_align",
                pair + " --expected_matrix_file=" + Quote(expected) +
                    " --output_json=" + Quote(expected),
                "output_json",
                {expected});
  // A new file, or one that is not an input, is fine.
  const ToolRun ok = testing::RunTool(
      "mlndt_align", pair + " --output_json=" + Quote(dir + "/result.json"));
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
}

TEST(OutputIsNotAnInput, MlndtMapPosesAndScanFolder) {
  const std::string dir = TestDir();
  const std::string poses = CopyOf("kitti/poses_velo.txt", dir);
  const std::string scans = Quote(testing::BundledDataPath("kitti/pcd"));
  ExpectRefused("mlndt_map",
                "--scans=" + scans + " --poses=" + Quote(poses) +
                    " --output=" + Quote(dir + "/map.mlndt") +
                    " --output_json=" + Quote(poses),
                "output_json",
                {poses});
  // A scan of the --scans folder (a point-cloud file in it).
  fs::create_directories(dir + "/pcd");
  const std::string scan = dir + "/pcd/000000.pcd";
  fs::copy_file(testing::BundledDataPath("kitti/pcd/000000.pcd"), scan);
  ExpectRefused("mlndt_map",
                "--scans=" + Quote(dir + "/pcd") + " --poses=" + Quote(poses) +
                    " --output=" + Quote(scan),
                "output",
                {scan});
  EXPECT_FALSE(fs::exists(dir + "/map.mlndt"));
}

TEST(OutputIsNotAnInput, MlndtConvertAndMlndtEval) {
  const std::string dir = TestDir();
  const std::string in = CopyOf("koide3/251370668.pcd", dir);
  ExpectRefused("mlndt_convert", Quote(in) + " " + Quote(in), "output", {in});
  ExpectRefused("mlndt_convert",
                "--input=" + Quote(in) + " --output=" + Quote(in),
                "output",
                {in});
  // OUT is an argument, not an input: an existing OUT is replaced.
  std::ofstream(dir + "/out.pcd") << "old";
  const ToolRun convert = testing::RunTool(
      "mlndt_convert", Quote(in) + " " + Quote(dir + "/out.pcd"));
  EXPECT_EQ(convert.exit_code, 0) << convert.err;
  EXPECT_NE(ReadWholeFile(dir + "/out.pcd"), "old");

  const std::string poses = CopyOf("kitti/poses_velo.txt", dir);
  ExpectRefused("mlndt_eval",
                "--reference=" + Quote(poses) + " --estimate=" + Quote(poses) +
                    " --output_json=" + Quote(poses),
                "output_json",
                {poses});
}

TEST(OutputIsNotAnInput, MlndtLocalizeOutputFolderHoldingItsInputs) {
  const std::string dir = TestDir();
  const std::string poses = CopyOf("kitti/poses_velo.txt", dir);
  fs::rename(poses, dir + "/trajectory_kitti.txt");
  const std::string map = dir + "/kitti.mlndt";
  const ToolRun built = testing::RunTool(
      "mlndt_map",
      "--scans=" + Quote(testing::BundledDataPath("kitti/pcd")) +
          " --poses=" + Quote(dir + "/trajectory_kitti.txt") +
          " --max_scans=1 --output=" + Quote(map));
  ASSERT_EQ(built.exit_code, 0) << built.err;
  // The first pose read from the file the run would write its trajectory to.
  ExpectRefused("mlndt_localize",
                "--map=" + Quote(map) +
                    " --scans=" + Quote(testing::BundledDataPath("kitti/pcd")) +
                    " --initial_poses=" + Quote(dir + "/trajectory_kitti.txt") +
                    " --plots=false --output_dir=" + Quote(dir),
                "output_dir",
                {dir + "/trajectory_kitti.txt", map});
}

}  // namespace
}  // namespace mlndt
