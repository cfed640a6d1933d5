// The figures of the plotting tools (lab/report/gnuplot.h): drawn into a
// private folder and moved onto their targets like every other output, so
// that a symbolic link, a FIFO or a full disk at a target never costs the
// previous file or hangs the tool (issue 27, item 9).

#include "lab/report/gnuplot.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/testing/run_tool.h"
#include "tests/testing/small_file_system.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

namespace fs = std::filesystem;
using testing::ReadWholeFile;

bool GnuplotInstalled() { return GnuplotAvailable("gnuplot"); }

// A script drawing y = x into `png`.
std::string LineScript(const std::string& png) {
  return GnuplotPngHeader(200, 150) + GnuplotSetOutput(png) + "plot x\n";
}

bool IsPng(const std::string& bytes) {
  return bytes.size() > 20 && bytes.compare(1, 3, "PNG") == 0 &&
         bytes.compare(bytes.size() - 8, 4, "IEND") == 0;
}

// Only the files the test made: no render folder or temporary left.
void ExpectNoLeftovers(const std::string& dir) {
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    EXPECT_EQ(name.find(".mlndt_plot."), std::string::npos) << name;
    EXPECT_EQ(name.find(".tmp."), std::string::npos) << name;
  }
}

TEST(RunGnuplot, DrawsTheFigureAndTheSavedScriptStillRunsByHand) {
  if (!GnuplotInstalled()) GTEST_SKIP() << "gnuplot is not installed";
  const std::string dir = testing::FreshTestDir("gnuplot");
  const std::string png = dir + "/line.png";
  std::string error;
  ASSERT_TRUE(
      RunGnuplot("gnuplot", dir + "/line.gp", LineScript(png), {png}, &error))
      << error;
  EXPECT_TRUE(IsPng(ReadWholeFile(png)));
  ExpectNoLeftovers(dir);
  // By hand (no render folder): the script draws at the path it names.
  fs::remove(png);
  ASSERT_EQ(
      std::system(("gnuplot " + testing::ShellQuote(dir + "/line.gp")).c_str()),
      0);
  EXPECT_TRUE(IsPng(ReadWholeFile(png)));
}

TEST(RunGnuplot, SymlinkAtTheFigureIsNeitherFollowedNorReplaced) {
  if (!GnuplotInstalled()) GTEST_SKIP() << "gnuplot is not installed";
  const std::string dir = testing::FreshTestDir("gnuplot");
  const std::string victim = dir + "/victim.txt";
  std::ofstream(victim) << "precious";
  const std::string png = dir + "/line.png";
  fs::create_symlink(victim, png);
  std::string error;
  EXPECT_FALSE(
      RunGnuplot("gnuplot", dir + "/line.gp", LineScript(png), {png}, &error));
  EXPECT_NE(error.find(png + ": cannot write: it is a symbolic link"),
            std::string::npos)
      << error;
  EXPECT_EQ(ReadWholeFile(victim), "precious");
  EXPECT_TRUE(fs::is_symlink(png));
  ExpectNoLeftovers(dir);
}

TEST(RunGnuplot, FailingScriptWithAFifoAtItsLogNeitherHangsNorOpensIt) {
  if (!GnuplotInstalled()) GTEST_SKIP() << "gnuplot is not installed";
  const std::string dir = testing::FreshTestDir("gnuplot");
  const std::string script = dir + "/bad.gp";
  ASSERT_EQ(::mkfifo((script + ".log").c_str(), 0644), 0);
  std::string error;
  EXPECT_FALSE(RunGnuplot(
      "gnuplot", script, "plot no_such_function_here(x)\n", {}, &error));
  // The log cannot go to the FIFO: its text is in the message.
  EXPECT_NE(error.find("gnuplot failed on " + script), std::string::npos)
      << error;
  EXPECT_NE(error.find("it is a FIFO"), std::string::npos) << error;
  EXPECT_NE(error.find("no_such_function_here"), std::string::npos) << error;
  EXPECT_EQ(fs::status(script + ".log").type(), fs::file_type::fifo);
  // Without the FIFO the log is kept next to the script.
  fs::remove(script + ".log");
  EXPECT_FALSE(RunGnuplot(
      "gnuplot", script, "plot no_such_function_here(x)\n", {}, &error));
  EXPECT_NE(error.find("(see " + script + ".log)"), std::string::npos) << error;
  EXPECT_NE(ReadWholeFile(script + ".log").find("no_such_function_here"),
            std::string::npos);
  ExpectNoLeftovers(dir);
}

TEST(RunGnuplot, FullDiskKeepsThePreviousFigure) {
  if (!GnuplotInstalled()) GTEST_SKIP() << "gnuplot is not installed";
  testing::SmallFileSystem fs_small;
  MLNDT_MOUNT_SMALL_FS_OR_SKIP(fs_small, 1 << 20);
  const std::string dir = fs_small.path();
  const std::string png = dir + "/line.png";
  std::string error;
  ASSERT_TRUE(
      RunGnuplot("gnuplot", dir + "/line.gp", LineScript(png), {png}, &error))
      << error;
  const std::string previous = ReadWholeFile(png);
  ASSERT_TRUE(IsPng(previous));
  fs_small.Fill();
  // A bigger figure does not fit.
  const std::string big = GnuplotPngHeader(1600, 1200) + GnuplotSetOutput(png) +
                          "plot sin(x) with dots\n";
  EXPECT_FALSE(RunGnuplot("gnuplot", dir + "/line.gp", big, {png}, &error));
  EXPECT_FALSE(error.empty());
  EXPECT_EQ(ReadWholeFile(png), previous);
  fs::remove(dir + "/filler");
  ExpectNoLeftovers(dir);
}

// A plotting tool run with a symbolic link at one of its figures and a FIFO
// at its gnuplot log: it neither writes through the link nor hangs on the
// FIFO, exits 1 naming the figure, and leaves both as they were.
struct PlantedRun {
  std::string tool;
  std::string args;
  std::string png;  // The figure the link is planted at.
  std::string log;  // The gnuplot log the FIFO is planted at.
  // 1: refused when drawing; 2: refused before the run (the tool checks
  // its figures' paths with its other outputs).
  int exit_code = 1;
};

void ExpectFiguresNotWrittenThroughPlantedFiles(const PlantedRun& p) {
  fs::create_directories(fs::path(p.log).parent_path());
  const std::string victim =
      fs::path(p.png).parent_path().parent_path().string() + "/victim.txt";
  std::ofstream(victim) << "precious";
  fs::create_symlink(victim, p.png);
  ASSERT_EQ(::mkfifo(p.log.c_str(), 0644), 0);
  const testing::ToolRun run =
      testing::RunTool(p.tool, p.args, /*timeout_s=*/180);
  ASSERT_NE(run.exit_code, 124) << p.tool << " hung on the FIFO " << p.log;
  EXPECT_EQ(run.exit_code, p.exit_code) << run.err;
  EXPECT_NE(run.err.find(p.png + ": cannot write: it is a symbolic link"),
            std::string::npos)
      << run.err;
  EXPECT_EQ(ReadWholeFile(victim), "precious");
  EXPECT_TRUE(fs::is_symlink(p.png));
  EXPECT_EQ(fs::status(p.log).type(), fs::file_type::fifo);
}

std::string Kitti(const std::string& name) {
  return testing::ShellQuote(testing::BundledDataPath("kitti/" + name));
}

TEST(PlottingTools, MlndtLocalize) {
  if (!GnuplotInstalled()) GTEST_SKIP() << "gnuplot is not installed";
  const std::string dir = testing::FreshTestDir("gnuplot");
  const std::string map = dir + "/kitti.mlndt";
  const testing::ToolRun built = testing::RunTool(
      "mlndt_map",
      "--scans=" + Kitti("pcd") + " --poses=" + Kitti("poses_velo.txt") +
          " --max_scans=2 --voxel_size=0.2 --output=" +
          testing::ShellQuote(map));
  ASSERT_EQ(built.exit_code, 0) << built.err;
  const std::string out = dir + "/out";
  ExpectFiguresNotWrittenThroughPlantedFiles(
      {"mlndt_localize",
       "--map=" + testing::ShellQuote(map) + " --scans=" + Kitti("pcd") +
           " --max_scans=1 --output_dir=" + testing::ShellQuote(out),
       out + "/trajectory_xy.png",
       out + "/plot_data/plot.gp.log"});
}

TEST(PlottingTools, MlndtSequence) {
  if (!GnuplotInstalled()) GTEST_SKIP() << "gnuplot is not installed";
  const std::string out = testing::FreshTestDir("gnuplot") + "/out";
  ExpectFiguresNotWrittenThroughPlantedFiles(
      {"mlndt_sequence",
       "--scans=" + Kitti("pcd") + " --gt_poses=" + Kitti("poses_velo.txt") +
           " --max_scans=2 --backend=lm --output_dir=" +
           testing::ShellQuote(out),
       out + "/trajectory_xy.png",
       out + "/plot_data/plots.gp.log",
       2});
}

TEST(PlottingTools, MlndtScaling) {
  if (!GnuplotInstalled()) GTEST_SKIP() << "gnuplot is not installed";
  const std::string out = testing::FreshTestDir("gnuplot") + "/out";
  ExpectFiguresNotWrittenThroughPlantedFiles(
      {"mlndt_scaling",
       "--sizes=4000 --repetitions=1 --output_dir=" + testing::ShellQuote(out),
       out + "/scaling.png",
       out + "/scaling.gp.log"});
}

TEST(PlottingTools, MlndtSuite) {
  if (!GnuplotInstalled()) GTEST_SKIP() << "gnuplot is not installed";
  const std::string out = testing::FreshTestDir("gnuplot") + "/out";
  ExpectFiguresNotWrittenThroughPlantedFiles(
      {"mlndt_suite",
       "--datasets=" + testing::ShellQuote(testing::BundledDataPath("koide3")) +
           " --starts=identity,offsets --offsets=yaw:10,150 "
           "--yaw_seeds_deg= --plot --output_dir=" +
           testing::ShellQuote(out),
       out + "/quality.png",
       out + "/plot_data/quality.gp.log"});
}

}  // namespace
}  // namespace mlndt
