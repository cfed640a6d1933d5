// Runs tools/mlndt_bag.py (Debian's python3-rosbag) and reads what it wrote
// with the tools' bag reader: the scan files' points, the stamps and the
// per-point times asked for; bad input refused with exit code 2 and no file
// written.

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "lab/io/ros_bag_scans.h"
#include "mlndt/cloud/io.h"
#include "tests/testing/run_tool.h"
#include "tests/testing/test_bag.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

namespace fs = std::filesystem;
using testing::ShellQuote;

struct BagToolRun {
  int exit_code = -1;
  std::string out;
  std::string err;
};

// /usr/bin/python3 tools/mlndt_bag.py `args` (quoted by the caller).
BagToolRun RunBagTool(const std::string& dir, const std::string& args) {
  const std::string tool = testing::BundledDataPath("../tools/mlndt_bag.py");
  const std::string err_path = dir + "/stderr.txt";
  const std::string command = "timeout -k 5 120 /usr/bin/python3 " +
                              ShellQuote(tool) + " " + args + " 2>" +
                              ShellQuote(err_path);
  BagToolRun run;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return run;
  char buffer[4096];
  size_t n;
  while ((n = fread(buffer, 1, sizeof(buffer), pipe)) > 0) {
    run.out.append(buffer, n);
  }
  const int status = pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.err = testing::ReadWholeFile(err_path);
  return run;
}

std::unique_ptr<RosBagScans> OpenBag(const std::string& bag,
                                     const std::string& topic) {
  std::unique_ptr<RosBagScans> scans;
  std::string error;
  EXPECT_TRUE(RosBagScans::Open(bag, topic, &scans, &error)) << error;
  return scans;
}

// A folder of the bundled KITTI scans at a fixed rate with a time ramp:
// each message reads point for point as its PCD file.
TEST(MlndtBag, FolderAtARateWithATimeRampReadsAsThePcdFiles) {
  MLNDT_REQUIRE_ROSBAG();
  const std::string dir = testing::FreshTestDir("mlndt_bag");
  const std::string bag = dir + "/kitti.bag";
  const BagToolRun run = RunBagTool(
      dir,
      "--output=" + ShellQuote(bag) + " --rate=10 --start=50 --max_scans=3 " +
          "--topic=/velodyne_points --frame_id=velodyne " +
          "--point_times=step:1e-6 " +
          ShellQuote(testing::BundledDataPath("kitti/pcd")));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("3 clouds on /velodyne_points"), std::string::npos)
      << run.out;
  std::unique_ptr<RosBagScans> scans = OpenBag(bag, "/velodyne_points");
  ASSERT_NE(scans, nullptr);
  ASSERT_EQ(scans->size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    PointCloud pcd;
    std::string error;
    ASSERT_TRUE(
        ReadPointCloud(testing::BundledDataPath("kitti/pcd/00000" +
                                                std::to_string(i) + ".pcd"),
                       &pcd,
                       nullptr,
                       &error));
    BagScan scan;
    ASSERT_TRUE(scans->Read(i, &scan, &error)) << error;
    EXPECT_EQ(scan.stamp_s, 50.0 + 0.1 * static_cast<double>(i));
    EXPECT_EQ(scan.frame_id, "velodyne");
    EXPECT_EQ(scan.time_field, "time");
    ASSERT_EQ(scan.cloud.points(), pcd.points());
    for (size_t k = 0; k < pcd.size(); k += 997) {
      ASSERT_EQ(scan.point_times_s[k],
                static_cast<double>(static_cast<float>(k * 1e-6)));
    }
  }
}

// Stamps from a file (a repeated one written with a warning), a
// binary_compressed PCD (LZF) and a per-point time field of an ascii PCD.
TEST(MlndtBag, TimesFileCompressedPcdAndATimeField) {
  MLNDT_REQUIRE_ROSBAG();
  const std::string dir = testing::FreshTestDir("mlndt_bag");
  std::ofstream(dir + "/times.txt") << "# stamps\n7.5 x\n7.5\n";
  std::ofstream(dir + "/t.pcd")
      << "VERSION 0.7\nFIELDS x y z t\nSIZE 4 4 4 8\nTYPE F F F F\n"
      << "COUNT 1 1 1 1\nWIDTH 2\nHEIGHT 1\nPOINTS 2\nDATA ascii\n"
      << "1 2 3 0.015625\n4 5 6 -0.03125\n";
  const std::string room = testing::BundledDataPath("room/room_scan1.pcd");
  const std::string bag = dir + "/b.bag";
  const BagToolRun refused =
      RunBagTool(dir,
                 "--output=" + ShellQuote(bag) +
                     " --times=" + ShellQuote(dir + "/times.txt") +
                     " --point_times=field:t " + ShellQuote(room) + " " +
                     ShellQuote(dir + "/t.pcd"));
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("room_scan1.pcd: no field t"), std::string::npos)
      << refused.err;
  EXPECT_FALSE(fs::exists(bag));

  const BagToolRun run =
      RunBagTool(dir,
                 "--output=" + ShellQuote(bag) +
                     " --times=" + ShellQuote(dir + "/times.txt") + " " +
                     ShellQuote(room) + " " + ShellQuote(dir + "/t.pcd"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find("stamp 1 (7.5) is not after the one before"),
            std::string::npos)
      << run.err;
  std::unique_ptr<RosBagScans> scans = OpenBag(bag, "/points");
  ASSERT_NE(scans, nullptr);
  ASSERT_EQ(scans->size(), 2u);
  PointCloud pcd;
  BagScan scan;
  std::string error;
  ASSERT_TRUE(ReadPointCloud(room, &pcd, nullptr, &error)) << error;
  ASSERT_TRUE(scans->Read(0, &scan, &error)) << error;
  EXPECT_EQ(scan.stamp_s, 7.5);
  EXPECT_EQ(scan.cloud.points(), pcd.points());
  EXPECT_TRUE(scan.point_times_s.empty());

  const BagToolRun with_times =
      RunBagTool(dir,
                 "--output=" + ShellQuote(dir + "/t.bag") + " --rate=1 " +
                     "--point_times=field:t " + ShellQuote(dir + "/t.pcd"));
  ASSERT_EQ(with_times.exit_code, 0) << with_times.err;
  ASSERT_TRUE(OpenBag(dir + "/t.bag", "/points")->Read(0, &scan, &error));
  EXPECT_EQ(scan.point_times_s, (std::vector<double>{0.015625, -0.03125}));
  EXPECT_EQ(scan.cloud[1], Eigen::Vector3d(4, 5, 6));
}

// Bad input: exit code 2, a message naming it, no bag written and an
// existing one untouched; a bag that cannot be written: exit code 1.
TEST(MlndtBag, BadInputIsRefusedBeforeAnyWork) {
  MLNDT_REQUIRE_ROSBAG();
  const std::string dir = testing::FreshTestDir("mlndt_bag");
  const std::string scan = ShellQuote(testing::BundledDataPath("kitti/pcd"));
  const std::string out = ShellQuote(dir + "/out.bag");
  std::ofstream(dir + "/two.txt") << "1\n2\n";
  std::ofstream(dir + "/no_z.pcd")
      << "FIELDS x y\nSIZE 4 4\nTYPE F F\nCOUNT 1 1\nPOINTS 0\nDATA ascii\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--output=" + out + " " + scan, "give --times=FILE or --rate=HZ"},
      {"--output=" + out +
           " --rate=10 --times=" + ShellQuote(dir + "/two.txt") + " " + scan,
       "give --times=FILE or --rate=HZ"},
      {"--output=" + out + " --times=" + ShellQuote(dir + "/two.txt") + " " +
           scan,
       "has 2 stamps for 8 scans"},
      {"--output=" + out + " --rate=10 " + ShellQuote(dir + "/missing.pcd"),
       "missing.pcd: no such file or folder"},
      {"--output=" + out + " --rate=10 " + ShellQuote(dir + "/no_z.pcd"),
       "no_z.pcd: no float field z"},
      {"--output=" + out + " --rate=10 --point_times=ramp " + scan,
       "--point_times=ramp: expected none, step:SECONDS or field:NAME"},
      {"--output=" + out + " --rate=-1 " + scan, "--rate must be > 0"},
      {"--output=" + out + " --rate=10 --start=0 " + scan,
       "stamp 0 is 0.0: ROS stamps must be in (0, 2^32) s"},
      {"--rate=10 " + scan, "the following arguments are required: --output"},
  };
  for (const auto& [args, message] : cases) {
    const BagToolRun run = RunBagTool(dir, args);
    EXPECT_EQ(run.exit_code, 2) << args;
    EXPECT_NE(run.err.find(message), std::string::npos) << args << "\n"
                                                        << run.err;
    EXPECT_FALSE(fs::exists(dir + "/out.bag")) << args;
  }
  std::ofstream(dir + "/out.bag") << "keep";
  const BagToolRun exists =
      RunBagTool(dir, "--output=" + out + " --rate=10 " + scan);
  EXPECT_EQ(exists.exit_code, 2);
  EXPECT_NE(exists.err.find("exists (give --force to replace it)"),
            std::string::npos);
  EXPECT_EQ(testing::ReadWholeFile(dir + "/out.bag"), "keep");

  const BagToolRun unwritable =
      RunBagTool(dir,
                 "--output=" + ShellQuote(dir + "/no/such/folder.bag") +
                     " --rate=10 " + scan);
  EXPECT_EQ(unwritable.exit_code, 1) << unwritable.err;
  EXPECT_NE(unwritable.err.find("writing"), std::string::npos)
      << unwritable.err;
  const BagToolRun help = RunBagTool(dir, "--help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("Exit codes: 0 written"), std::string::npos);
}

}  // namespace
}  // namespace mlndt
