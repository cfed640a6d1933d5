// Runs the built mlndt_map on the bundled KITTI frames with the poses chained
// from reference_pairs.json (by mlndt_eval chain): the counts it reports
// against counts made here, the saved map against a map built here from the
// same cloud, KITTI/TUM/camera poses, --cloud, --scan_list, `info`, the
// memory limit at each stage, and every flag it refuses.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "lab/eval/dataset.h"
#include "lab/eval/trajectory_io.h"
#include "mlndt/cloud/io.h"
#include "mlndt/cloud/pose_io.h"
#include "mlndt/grid/grid_io.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/pipeline/map_builder.h"
#include "mlndt/sampling/point_sampler.h"
#include "tests/testing/run_tool.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

using testing::ToolRun;
const auto& Quote = testing::ShellQuote;
namespace fs = std::filesystem;
using Json = nlohmann::json;

std::string TestDir() { return testing::FreshTestDir("mlndt_map"); }

std::string KittiPcd() { return testing::BundledDataPath("kitti/pcd"); }

// The chained reference poses of the 8 frames, written by mlndt_eval chain
// into `dir`.
std::string ChainedPoses(const std::string& dir) {
  const std::string path = dir + "/chained.txt";
  const ToolRun run = testing::RunTool(
      "mlndt_eval",
      "chain " + Quote(testing::BundledDataPath("kitti/reference_pairs.json")) +
          " " + Quote(path));
  EXPECT_EQ(run.exit_code, 0) << run.err;
  return path;
}

ToolRun RunMap(const std::string& args) {
  return testing::RunTool("mlndt_map", args);
}

Json ReadJson(const std::string& path) {
  std::ifstream in(path);
  Json json;
  in >> json;
  return json;
}

LayeredGrid LoadMap(const std::string& path) {
  LayeredGrid map;
  std::string error;
  EXPECT_TRUE(LoadLayeredGrid(path, &map, &error)) << error;
  return map;
}

// Same layers; cells matched by key. With max_fraction = 0 the cells and
// keys are the same and every mean is within `tolerance` [m]. Poses that
// differ by rounding (a TUM quaternion, a calibration round trip) move a few
// points across cell borders, which changes those cells' means by
// centimetres or drops a sparse cell: then at most `max_fraction` of the
// cells may be missing or have a mean further off than `tolerance` (at
// least one: a coarse layer has few cells, and a point that changes finest
// cell changes the weights of a coarse cell's moments).
void ExpectSameMap(const LayeredGrid& a,
                   const LayeredGrid& b,
                   double tolerance,
                   double max_fraction = 0.0) {
  ASSERT_EQ(a.num_layers(), b.num_layers());
  for (int i = 1; i <= a.num_layers(); ++i) {
    SCOPED_TRACE("layer " + std::to_string(i));
    const NdtLayer& la = a.layer(i);
    const NdtLayer& lb = b.layer(i);
    ASSERT_EQ(la.dims(), lb.dims());
    if (max_fraction == 0.0) ASSERT_EQ(la.keys(), lb.keys());
    std::map<int64_t, size_t> b_slots;
    for (size_t c = 0; c < lb.keys().size(); ++c) b_slots[lb.keys()[c]] = c;
    size_t off = 0;
    for (size_t c = 0; c < la.keys().size(); ++c) {
      const auto it = b_slots.find(la.keys()[c]);
      if (it == b_slots.end() ||
          (la.cells()[c].mean - lb.cells()[it->second].mean)
                  .cwiseAbs()
                  .maxCoeff() > tolerance) {
        ++off;
      }
    }
    const size_t cells = std::max(la.keys().size(), lb.keys().size());
    off += cells - la.keys().size();
    const double allowed =
        max_fraction == 0.0
            ? 0.0
            : std::max(1.0, max_fraction * static_cast<double>(cells));
    EXPECT_LE(static_cast<double>(off), allowed)
        << off << " of " << cells << " cells differ";
  }
}

// The 8 frames, cropped to [min, max] m and moved by `poses`, merged here.
PointCloud MergeHere(const std::vector<Isometry3d>& poses,
                     double min_range,
                     double max_range,
                     size_t* read,
                     size_t* cropped) {
  std::vector<std::string> paths;
  std::string error;
  EXPECT_TRUE(ListScanFiles(KittiPcd(), {}, &paths, &error)) << error;
  PointCloud merged;
  *read = *cropped = 0;
  for (size_t k = 0; k < paths.size(); ++k) {
    PointCloud scan;
    EXPECT_TRUE(ReadPointCloud(paths[k], &scan, nullptr, &error)) << error;
    *read += scan.size();
    for (const Eigen::Vector3d& p : scan.points()) {
      const double r2 = p.squaredNorm();
      if (r2 < min_range * min_range || r2 > max_range * max_range) {
        ++*cropped;
        continue;
      }
      merged.Add(poses[k] * p);
    }
  }
  return merged;
}

TEST(MlndtMap, BuildsTheKittiMapFromChainedPoses) {
  const std::string dir = TestDir();
  const std::string poses_path = ChainedPoses(dir);
  const std::string map_path = dir + "/kitti.mlndt";
  const ToolRun run =
      RunMap("--scans=" + Quote(KittiPcd()) + " --poses=" + Quote(poses_path) +
             " --min_range_m=3 --max_range_m=80 --voxel_size=0.2 --output=" +
             Quote(map_path) + " --output_json=" + Quote(dir + "/map.json"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("map written to " + map_path), std::string::npos);
  EXPECT_NE(run.err.find("mlndt_map 8/8 000007.pcd"), std::string::npos)
      << run.err;  // Progress.

  std::vector<Isometry3d> poses;
  std::string error;
  ASSERT_TRUE(ReadKittiPoses(poses_path, &poses, &error)) << error;
  size_t read = 0, cropped = 0;
  const PointCloud merged = MergeHere(poses, 3.0, 80.0, &read, &cropped);
  const PointCloud filtered = VoxelDownsample(merged, 0.2);
  const Json json = ReadJson(dir + "/map.json");
  EXPECT_EQ(json["schema_version"], 2);
  EXPECT_EQ(json["tool"], "mlndt_map");
  EXPECT_GT(json["total_time_s"].get<double>(),
            json["build_time_s"].get<double>());
  // The summary's keys are its table's (MapBuildSummaryTable).
  for (const ResultField& field : MapBuildSummaryTable().fields()) {
    EXPECT_TRUE(json.contains(field.name)) << field.name;
  }
  EXPECT_EQ(json["scans_without_points"].size(), 0u);
  EXPECT_EQ(json["scans"].get<size_t>(), 8u);
  EXPECT_EQ(json["input_points"].get<size_t>(), read);
  EXPECT_EQ(json["cropped_points"].get<size_t>(), cropped);
  EXPECT_GT(cropped, 0u);
  EXPECT_EQ(json["merged_points"].get<size_t>(), merged.size());
  EXPECT_EQ(json["map_points"].get<size_t>(), filtered.size());
  EXPECT_EQ(json["memory"]["map_bytes"].get<size_t>(),
            json["map_bytes"].get<size_t>());
  EXPECT_EQ(json["memory"]["layers"].size(), json["layers"].size());
  EXPECT_EQ(json["max_memory_bytes"].get<size_t>(), size_t{8000000000});

  LayeredGrid here;
  ASSERT_TRUE(LayeredGrid::Build(LayeredGridOptions(), filtered, &here, &error))
      << error;
  const LayeredGrid saved = LoadMap(map_path);
  ExpectSameMap(saved, here, 1e-9);
  EXPECT_EQ(json["layers"].size(), static_cast<size_t>(here.num_layers()));
  EXPECT_EQ(json["map_bytes"].get<size_t>(), here.MemoryBytes());
}

// The same poses as a TUM file, and as KITTI camera poses with
// --poses_are_camera --calib,
// give the same map; --scan_list gives the same map as --scans. (The
// chained rotations are orthonormal only to ~5e-6, as the 9-digit pairs
// are; TUM's quaternions are exact rotations, so points 80 m out move by
// up to ~0.2 mm.)
TEST(MlndtMap, TumPosesCameraPosesAndScanLists) {
  const std::string dir = TestDir();
  const std::string kitti = ChainedPoses(dir);
  std::string error;
  std::vector<Isometry3d> poses;
  ASSERT_TRUE(ReadKittiPoses(kitti, &poses, &error));
  ASSERT_TRUE(WriteTrajectory(
      dir + "/poses.tum", TrajectoryFormat::TUM, Trajectory(poses), &error));
  const std::string common = " --max_range_m=60 ";
  ASSERT_EQ(RunMap("--scans=" + Quote(KittiPcd()) + " --poses=" + Quote(kitti) +
                   common + "--output=" + Quote(dir + "/a.mlndt"))
                .exit_code,
            0);
  const ToolRun tum = RunMap("--scans=" + Quote(KittiPcd()) +
                             " --poses=" + Quote(dir + "/poses.tum") + common +
                             "--output=" + Quote(dir + "/b.mlndt"));
  ASSERT_EQ(tum.exit_code, 0) << tum.err;
  ExpectSameMap(
      LoadMap(dir + "/a.mlndt"), LoadMap(dir + "/b.mlndt"), 1e-3, 0.05);

  // Relative paths are relative to the list's folder; comments skipped.
  {
    std::ofstream list(dir + "/scans.txt");
    list << "# the bundled frames\n";
    for (int k = 0; k < 8; ++k) {
      list << fs::relative(KittiPcd() + "/00000" + std::to_string(k) + ".pcd",
                           dir)
                  .string()
           << "\n";
    }
  }
  const ToolRun listed = RunMap("--scan_list=" + Quote(dir + "/scans.txt") +
                                " --poses=" + Quote(kitti) + common +
                                "--output=" + Quote(dir + "/c.mlndt"));
  ASSERT_EQ(listed.exit_code, 0) << listed.err;
  ExpectSameMap(LoadMap(dir + "/a.mlndt"), LoadMap(dir + "/c.mlndt"), 0.0);

  // KITTI's own ground truth: camera poses + calib = Velodyne poses.
  const ToolRun velo =
      RunMap("--scans=" + Quote(KittiPcd()) + " --poses=" +
             Quote(testing::BundledDataPath("kitti/poses_velo.txt")) + common +
             "--output=" + Quote(dir + "/velo.mlndt"));
  const ToolRun camera =
      RunMap("--scans=" + Quote(KittiPcd()) + " --poses=" +
             Quote(testing::BundledDataPath("kitti/poses_cam0.txt")) +
             " --poses_are_camera --calib=" +
             Quote(testing::BundledDataPath("kitti/calib.txt")) + common +
             "--output=" + Quote(dir + "/camera.mlndt"));
  ASSERT_EQ(velo.exit_code, 0) << velo.err;
  ASSERT_EQ(camera.exit_code, 0) << camera.err;
  ExpectSameMap(
      LoadMap(dir + "/velo.mlndt"), LoadMap(dir + "/camera.mlndt"), 1e-3, 0.05);
}

TEST(MlndtMap, BuildsFromOneCloudAndDescribesAMap) {
  const std::string dir = TestDir();
  const std::string cloud = KittiPcd() + "/000000.pcd";
  const ToolRun run = RunMap("--cloud=" + Quote(cloud) +
                             " --finest_cell_size_m=1 --min_points_per_cell=6 "
                             "--output=" +
                             Quote(dir + "/one.mlndt") +
                             " --output_json=" + Quote(dir + "/one.json"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  PointCloud points;
  std::string error;
  ASSERT_TRUE(ReadPointCloud(cloud, &points, nullptr, &error));
  const Json json = ReadJson(dir + "/one.json");
  EXPECT_EQ(json["input_points"].get<size_t>(), points.size());
  EXPECT_EQ(json["map_points"].get<size_t>(), points.size());
  LayeredGridOptions options;
  options.finest_cell_size_m = 1.0;
  options.min_points_per_cell = 6;
  LayeredGrid here;
  ASSERT_TRUE(LayeredGrid::Build(options, points, &here, &error));
  const LayeredGrid saved = LoadMap(dir + "/one.mlndt");
  ExpectSameMap(saved, here, 1e-9);
  EXPECT_EQ(saved.options().min_points_per_cell, 6);

  const ToolRun info = RunMap("info " + Quote(dir + "/one.mlndt"));
  ASSERT_EQ(info.exit_code, 0) << info.err;
  EXPECT_NE(info.out.find("points: " + std::to_string(points.size())),
            std::string::npos)
      << info.out;
  EXPECT_NE(info.out.find("extent: ("), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("min points per cell 6"), std::string::npos);
  size_t cells = 0;
  for (int i = 1; i <= saved.num_layers(); ++i) {
    cells += saved.layer(i).cells().size();
    const NdtLayer& layer = saved.layer(i);
    char row[128];
    std::snprintf(row, sizeof(row), "%-5d %10.4f", i, layer.cell_size());
    EXPECT_NE(info.out.find(row), std::string::npos) << row << "\n" << info.out;
  }
  EXPECT_NE(
      info.out.find("cells: " + std::to_string(cells) + " over " +
                    std::to_string(saved.num_layers()) + " layers, map bytes " +
                    std::to_string(saved.MemoryBytes())),
      std::string::npos)
      << info.out;
}

// A build over --max_memory_gb is refused at the stage that would pass it,
// naming the limit, and writes no map.
TEST(MlndtMap, RefusesWhatExceedsTheMemoryLimit) {
  const std::string dir = TestDir();
  const std::string poses = ChainedPoses(dir);
  const std::string out = dir + "/refused.mlndt";
  struct Case {
    std::string args;
    std::string message;
  } cases[] = {
      {"--scans=" + Quote(KittiPcd()) + " --poses=" + Quote(poses) +
           " --max_memory_gb=0.03",
       "merging scan 4"},
      {"--scans=" + Quote(KittiPcd()) + " --poses=" + Quote(poses) +
           " --voxel_size=0.2 --max_memory_gb=0.06",
       "the voxel filter of 991949 points"},
      {"--cloud=" + Quote(KittiPcd() + "/000000.pcd") +
           " --finest_cell_size_m=0.1 --max_memory_gb=0.01",
       "to build the map"},
  };
  for (const Case& c : cases) {
    const ToolRun run = RunMap(c.args + " --output=" + Quote(out));
    EXPECT_EQ(run.exit_code, 1) << c.args;
    EXPECT_NE(run.err.find(c.message), std::string::npos)
        << c.args << "\nstderr: " << run.err;
    EXPECT_NE(run.err.find("memory limit of"), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(out));
  }
  // No limit: the same fine map builds. (At 0.05 m its finest layer would
  // have no occupied cell, a map CheckMapUsable refuses.)
  const ToolRun unlimited = RunMap(
      "--cloud=" + Quote(KittiPcd() + "/000000.pcd") +
      " --finest_cell_size_m=0.1 --max_memory_gb=0 --output=" + Quote(out));
  EXPECT_EQ(unlimited.exit_code, 0) << unlimited.err;
}

// Every misconfiguration: exit code 1, a message naming the flag, and no
// work (no map written).
TEST(MlndtMap, RefusesBadFlags) {
  const std::string dir = TestDir();
  const std::string poses = ChainedPoses(dir);
  const std::string out = dir + "/never.mlndt";
  const std::string scans =
      "--scans=" + Quote(KittiPcd()) + " --poses=" + Quote(poses);
  const std::string to = " --output=" + Quote(out);
  struct Case {
    std::string args;
    std::string message;
  } cases[] = {
      {scans, "--output=MAP is required"},
      {to,
       "give --scans=DIR (or --scan_list=FILE, or --bag=FILE --topic=NAME) "
       "with --poses, or --cloud"},
      {"--scans=" + Quote(KittiPcd()) + to, "need --poses"},
      {scans + " --cloud=x.pcd" + to, "give --cloud or --scans/--scan_list"},
      {scans + " --scan_list=x.txt" + to,
       "give --scans=DIR or --scan_list=FILE, not both"},
      {"--cloud=x.pcd --poses=" + Quote(poses) + to,
       "--poses does not apply to --cloud"},
      {"--cloud=x.pcd --min_range_m=2" + to,
       "--min_range_m does not apply to --cloud"},
      {"--cloud=x.pcd --calib=c.txt" + to, "--calib does not apply to --cloud"},
      {"--cloud=x.pcd --poses_are_camera" + to,
       "--poses_are_camera does not apply to --cloud"},
      {scans + " --poses_are_camera" + to,
       "--poses_are_camera needs --calib=calib.txt"},
      {scans + " --calib=" +
           Quote(testing::BundledDataPath("kitti/calib.txt")) + to,
       "--calib converts camera poses: give --poses_are_camera with it"},
      {scans + " --min_range_m=-1" + to, "--min_range_m: invalid option"},
      {scans + " --min_range_m=5 --max_range_m=4" + to,
       "--max_range_m: invalid option"},
      {scans + " --voxel_size=-0.1" + to, "--voxel_size must be"},
      {scans + " --voxel_size=1e-5" + to, "--voxel_size must be"},
      {scans + " --max_memory_gb=-1" + to, "--max_memory_gb must be"},
      {scans + " --max_scans=-1" + to, "--max_scans must be >= 0"},
      {scans + " --poses_format=ply" + to,
       "--poses_format=ply: expected auto, kitti or tum"},
      {scans + " --division_constant=1" + to, "--division_constant"},
      {scans + " --finest_cell_size_m=-2" + to, "--finest_cell_size_m"},
      {scans + " --min_points_per_cell=2" + to, "--min_points_per_cell"},
      {scans + " --min_eigenvalue_ratio=2" + to, "--min_eigenvalue_ratio"},
      {scans + " --num_layers=3" + to, "--num_layers is ignored"},
      {scans + " --preset=fast" + to,
       "--preset=fast: expected default or paper"},
      {scans + " --backend=lm" + to, "--backend does not apply to mlndt_map"},
      {scans + " --sampling=all" + to,
       "--sampling does not apply to mlndt_map"},
      {scans + " --method=ndt" + to, "--method does not apply to mlndt_map"},
      {scans + " --num_threads=0" + to, "--num_threads must be in [1, 256]"},
      {scans + " --output=" + Quote(dir + "/map.pcd"),
       "map.pcd: a map is not a point cloud"},
      {scans + " --output=/nonexistent/folder/map.mlndt",
       "folder /nonexistent/folder does not exist"},
      {"--scans=/nonexistent --poses=" + Quote(poses) + to,
       "--scans: /nonexistent"},
      {"--scan_list=/nonexistent.txt --poses=" + Quote(poses) + to,
       "--scan_list: /nonexistent.txt"},
      {"--scans=" + Quote(KittiPcd()) + " --poses=/nonexistent.txt" + to,
       "--poses: /nonexistent.txt"},
      {"--scans=" + Quote(KittiPcd()) + " --poses=" +
           Quote(testing::BundledDataPath("kitti/calib.txt")) + to,
       "--poses:"},
      {"stray" + to, "unexpected argument 'stray'"},
      {"info", "usage: mlndt_map info MAP"},
      {"info a b", "usage: mlndt_map info MAP"},
      {"info /nonexistent.mlndt", "/nonexistent.mlndt"},
      {"info x.mlndt --voxel_size=1",
       "--voxel_size does not apply to 'mlndt_map info'"},
  };
  for (const Case& c : cases) {
    const ToolRun run = RunMap(c.args);
    EXPECT_EQ(run.exit_code, 2) << c.args;
    EXPECT_NE(run.err.find(c.message), std::string::npos)
        << c.args << "\nstderr: " << run.err;
    EXPECT_FALSE(fs::exists(out)) << c.args;
  }
  // Fewer poses than scans.
  {
    std::ofstream three(dir + "/three.txt");
    std::ifstream in(poses);
    std::string line;
    for (int k = 0; k < 3 && std::getline(in, line); ++k) three << line << "\n";
  }
  const ToolRun few = RunMap("--scans=" + Quote(KittiPcd()) +
                             " --poses=" + Quote(dir + "/three.txt") + to);
  EXPECT_EQ(few.exit_code, 2);
  EXPECT_NE(few.err.find("has 3 poses for 8 scans"), std::string::npos)
      << few.err;
}

// Issue 27 item 14: --help lists only the flags mlndt_map accepts. Each
// shared registration flag it does not read is refused (exit 2, named,
// nothing written) and left out of --help; --coarse_weighting, a property
// of the map, is read.
TEST(MlndtMap, HelpListsOnlyTheFlagsItAccepts) {
  const ToolRun help = testing::RunTool("mlndt_map", "--help");
  ASSERT_EQ(help.exit_code, 0);
  const std::string dir = testing::FreshTestDir("mlndt_map");
  const std::string cloud =
      " --cloud=" + Quote(testing::BundledDataPath("room/room_scan1.pcd"));
  const std::string map = dir + "/room.mlndt";
  const std::pair<const char*, const char*> refused[] = {
      {"method", "mlndt"},
      {"ndt_cell_size_m", "1"},
      {"ndt_outlier_ratio", "0.5"},
      {"ndt_neighbors", "direct7"},
      {"ndt_max_iterations", "9"},
      {"ndt_max_step_norm", "0.1"},
      {"backend", "lm"},
      {"sampling", "all"},
      {"random_fraction", "0.5"},
      {"gbs_cell_size_m", "1"},
      {"start_layer", "1"},
      {"iterations_per_layer", "3"},
      {"max_final_iterations", "9"},
      {"step_tolerance", "0.001"},
      {"coarse_step_tolerance", "0.01"},
      {"max_coarse_point_stride", "2"},
      {"unmatched_policy", "zero_residual"},
      {"loss", "huber"},
      {"loss_scale", "2"},
      {"linear_solver_type", "dense_qr"},
      {"trust_region_strategy_type", "dogleg"},
      {"seed", "3"},
      {"initial_uncertainty", "1,10"},
      {"quality_check", "true"},
      {"min_inlier_fraction", "0.3"},
      {"max_mean_score", "9"},
      {"inlier_gate", "3"},
      {"min_constraint_ratio", "0.1"},
      {"yaw_seeds_deg", "45"}};
  for (const auto& [flag, value] : refused) {
    EXPECT_EQ(help.out.find(std::string("  --") + flag + "="),
              std::string::npos)
        << flag << " is listed in --help";
    const ToolRun run = testing::RunTool(
        "mlndt_map",
        cloud + " --output=" + Quote(map) + " --" + flag + "=" + value);
    EXPECT_EQ(run.exit_code, 2) << flag << "\n" << run.err;
    EXPECT_NE(run.err.find(std::string("--") + flag + " does not apply"),
              std::string::npos)
        << run.err;
    EXPECT_FALSE(fs::exists(map)) << flag;
  }
  for (const char* accepted : {"scans",
                               "poses",
                               "calib",
                               "preset",
                               "num_threads",
                               "finest_cell_size_m",
                               "coarse_weighting",
                               "min_range_m",
                               "saturated_range_fraction"}) {
    EXPECT_NE(help.out.find(std::string("  --") + accepted + "="),
              std::string::npos)
        << accepted;
  }
  // --coarse_weighting changes the map it builds.
  const ToolRun finest =
      testing::RunTool("mlndt_map", cloud + " --output=" + Quote(map));
  ASSERT_EQ(finest.exit_code, 0) << finest.err;
  const ToolRun points =
      testing::RunTool("mlndt_map",
                       cloud + " --coarse_weighting=points --output=" +
                           Quote(dir + "/points.mlndt"));
  ASSERT_EQ(points.exit_code, 0) << points.err;
  EXPECT_NE(testing::ReadWholeFile(map),
            testing::ReadWholeFile(dir + "/points.mlndt"));
}

}  // namespace
}  // namespace mlndt

namespace mlndt {
namespace {

void WriteText(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
}

std::string AsciiPcd(const std::vector<std::string>& points) {
  std::string text =
      "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT "
      "1 1 1\nWIDTH " +
      std::to_string(points.size()) +
      "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " +
      std::to_string(points.size()) + "\nDATA ascii\n";
  for (const std::string& p : points) text += p + "\n";
  return text;
}

// Issue 27 item 3: a map that cannot be used is not written. A pose with
// 1e300 in it is refused by the pose reader (exit 2); five points give 0
// occupied cells (exit 1). The file at --output stays as it was.
TEST(MlndtMap, RefusesToWriteAnUnusableMap) {
  const std::string dir = TestDir();
  const std::string output = dir + "/map.mlndt";
  WriteText(output, "the previous map");
  std::vector<Isometry3d> poses;
  std::string error;
  ASSERT_TRUE(ReadKittiPoses(ChainedPoses(dir), &poses, &error)) << error;
  std::string text;
  for (size_t k = 0; k < poses.size(); ++k) {
    for (int e = 0; e < 12; ++e) {
      const double v =
          k == 2 && e == 3 ? 1e300 : poses[k].matrix()(e / 4, e % 4);
      text += (e ? " " : "") + std::to_string(v);
    }
    text += "\n";
  }
  WriteText(dir + "/huge.txt", text);
  const ToolRun huge = RunMap("--scans=" + Quote(KittiPcd()) +
                              " --poses=" + Quote(dir + "/huge.txt") +
                              " --output=" + Quote(output));
  EXPECT_EQ(huge.exit_code, 2) << huge.err;
  EXPECT_NE(huge.err.find("huge.txt: line 3: translation"), std::string::npos)
      << huge.err;
  EXPECT_NE(huge.err.find("is beyond 1e+08 m"), std::string::npos) << huge.err;

  WriteText(dir + "/five.pcd",
            AsciiPcd({"0 0 0", "1 0 0", "0 1 0", "0 0 1", "1 1 1"}));
  const ToolRun five = RunMap("--cloud=" + Quote(dir + "/five.pcd") +
                              " --output=" + Quote(output));
  EXPECT_EQ(five.exit_code, 1) << five.err;
  EXPECT_NE(five.err.find("the map is not usable: the map has 0 occupied "
                          "cells"),
            std::string::npos)
      << five.err;
  EXPECT_EQ(five.out.find("map written"), std::string::npos) << five.out;
  EXPECT_EQ(testing::ReadWholeFile(output), "the previous map");
  EXPECT_EQ(
      std::distance(fs::directory_iterator(dir), fs::directory_iterator()),
      4);  // chained.txt, huge.txt, five.pcd, map.mlndt: nothing new.
}

// Issue 27 item 6: a --scan_list entry that does not exist is found before
// any scan is read (exit 2), not after the others were merged (exit 1).
TEST(MlndtMap, MissingScanOfAListIsRefusedBeforeAnyWork) {
  const std::string dir = TestDir();
  const std::string missing = dir + "/missing.pcd";
  WriteText(dir + "/scans.txt", KittiPcd() + "/000000.pcd\n" + missing + "\n");
  const ToolRun run =
      RunMap("--scan_list=" + Quote(dir + "/scans.txt") +
             " --poses=" + Quote(ChainedPoses(dir)) +
             " --max_scans=2 --output=" + Quote(dir + "/map.mlndt"));
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find("--scan_list=" + dir + "/scans.txt: scan 1 (" +
                         missing + ") is not a readable file"),
            std::string::npos)
      << run.err;
  EXPECT_EQ(run.err.find("000000.pcd"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(dir + "/map.mlndt"));
}

// Issue 27 item 8: more poses than scans is refused (pose k belongs to
// scan k; --max_scans takes a prefix on purpose), and a scan without a
// finite point is named in a warning instead of adding nothing silently.
TEST(MlndtMap, PoseCountMismatchAndAnAllNanScan) {
  const std::string dir = TestDir();
  const std::string poses = ChainedPoses(dir);  // 8 poses.
  std::string list;
  for (int k = 0; k < 7; ++k) {
    list += KittiPcd() + "/00000" + std::to_string(k) + ".pcd\n";
  }
  WriteText(dir + "/seven.txt", list);
  const ToolRun seven = RunMap("--scan_list=" + Quote(dir + "/seven.txt") +
                               " --poses=" + Quote(poses) +
                               " --output=" + Quote(dir + "/seven.mlndt"));
  EXPECT_EQ(seven.exit_code, 2) << seven.err;
  EXPECT_NE(seven.err.find("has 8 poses for 7 scans"), std::string::npos)
      << seven.err;
  EXPECT_FALSE(fs::exists(dir + "/seven.mlndt"));

  const std::string nan = dir + "/all_nan.pcd";
  WriteText(nan, AsciiPcd({"nan nan nan", "nan nan nan", "nan nan nan"}));
  WriteText(
      dir + "/with_nan.txt",
      KittiPcd() + "/000000.pcd\n" + nan + "\n" + KittiPcd() + "/000002.pcd\n");
  const ToolRun with_nan =
      RunMap("--scan_list=" + Quote(dir + "/with_nan.txt") +
             " --poses=" + Quote(poses) +
             " --max_scans=3 --output=" + Quote(dir + "/nan.mlndt"));
  EXPECT_EQ(with_nan.exit_code, 0) << with_nan.err;
  EXPECT_NE(
      with_nan.err.find("warning: scan 1 (" + nan + ") has no finite point"),
      std::string::npos)
      << with_nan.err;
  EXPECT_TRUE(fs::exists(dir + "/nan.mlndt"));
}

}  // namespace
}  // namespace mlndt
