// Runs the built mlndt_localize on the bundled KITTI frames against a map
// built by mlndt_map from the poses chained from reference_pairs.json
// (mlndt_eval chain), started 10 m and 45 degrees off: every scan must land
// within 0.2 m and 1 degree of its chained reference. Also its outputs
// (trajectories, scans.csv, summary.json, the plot), the other ways to give
// the first pose, scan lists, the missing-gnuplot exit, and every flag it
// refuses.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "lab/eval/trajectory_io.h"
#include "mlndt/cloud/pose_io.h"
#include "mlndt/common/pose.h"
#include "tests/testing/run_tool.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

using testing::ToolRun;
const auto& Quote = testing::ShellQuote;
namespace fs = std::filesystem;
using Json = nlohmann::json;

std::string TestDir() { return testing::FreshTestDir("mlndt_localize"); }

std::string KittiPcd() { return testing::BundledDataPath("kitti/pcd"); }

bool GnuplotInstalled() {
  return std::system("gnuplot --version >/dev/null 2>&1") == 0;
}

// The chained reference poses and the map built from them, in `dir`.
struct KittiMap {
  std::string poses;
  std::string map;
};

KittiMap BuildKittiMap(const std::string& dir) {
  KittiMap m{dir + "/chained.txt", dir + "/kitti.mlndt"};
  const ToolRun chain = testing::RunTool(
      "mlndt_eval",
      "chain " + Quote(testing::BundledDataPath("kitti/reference_pairs.json")) +
          " " + Quote(m.poses));
  EXPECT_EQ(chain.exit_code, 0) << chain.err;
  const ToolRun map = testing::RunTool(
      "mlndt_map",
      "--scans=" + Quote(KittiPcd()) + " --poses=" + Quote(m.poses) +
          " --min_range_m=3 --max_range_m=80 --voxel_size=0.2 --output=" +
          Quote(m.map));
  EXPECT_EQ(map.exit_code, 0) << map.err;
  return m;
}

std::vector<Isometry3d> ReadPoses(const std::string& path) {
  std::vector<Isometry3d> poses;
  std::string error;
  EXPECT_TRUE(ReadKittiPoses(path, &poses, &error)) << error;
  return poses;
}

// The fields of one CSV line ("..." quoting with "" for a quote; no
// line breaks inside a field).
std::vector<std::string> CsvFields(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      fields.back() += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

// scans.csv as rows of named fields, in the header's order.
std::vector<std::vector<std::pair<std::string, std::string>>> ReadCsvRows(
    const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::vector<std::string> header;
  std::vector<std::vector<std::pair<std::string, std::string>>> rows;
  while (std::getline(in, line)) {
    const std::vector<std::string> fields = CsvFields(line);
    if (header.empty()) {
      header = fields;
      continue;
    }
    EXPECT_EQ(fields.size(), header.size()) << line;
    rows.emplace_back();
    for (size_t k = 0; k < header.size() && k < fields.size(); ++k) {
      rows.back().emplace_back(header[k], fields[k]);
    }
  }
  return rows;
}

std::vector<std::map<std::string, std::string>> ReadCsv(
    const std::string& path) {
  std::vector<std::map<std::string, std::string>> rows;
  for (const auto& row : ReadCsvRows(path)) {
    rows.emplace_back(row.begin(), row.end());
  }
  return rows;
}

// The leaves of a scans.json object named as the CSV's columns: nested
// objects as "outer.inner", lists of objects (the trace) left out.
void FlattenJson(const Json& object,
                 const std::string& prefix,
                 std::vector<std::pair<std::string, Json>>* leaves) {
  for (auto it = object.begin(); it != object.end(); ++it) {
    const Json& value = it.value();
    if (value.is_object()) {
      FlattenJson(value, prefix + it.key() + ".", leaves);
    } else if (!(value.is_array() && !value.empty() &&
                 value.front().is_object())) {
      leaves->emplace_back(prefix + it.key(), value);
    }
  }
}

// The numbers of a JSON value (nested arrays row by row; null as NaN).
void JsonNumbers(const Json& value, std::vector<double>* numbers) {
  if (value.is_array()) {
    for (const Json& item : value) JsonNumbers(item, numbers);
  } else {
    numbers->push_back(value.is_null() ? std::nan("") : value.get<double>());
  }
}

// A CSV cell holds the JSON value: the same text, or the same numbers.
void ExpectSameValue(const std::string& cell, const Json& value) {
  if (value.is_string()) {
    EXPECT_EQ(cell, value.get<std::string>());
    return;
  }
  if (value.is_boolean()) {
    EXPECT_EQ(cell, value.get<bool>() ? "true" : "false");
    return;
  }
  std::vector<double> expected, found;
  JsonNumbers(value, &expected);
  std::stringstream stream(cell);
  std::string number;
  while (stream >> number) found.push_back(std::stod(number));
  ASSERT_EQ(found.size(), expected.size()) << cell;
  for (size_t i = 0; i < found.size(); ++i) {
    if (std::isnan(expected[i])) {
      EXPECT_FALSE(std::isfinite(found[i])) << cell;
    } else {
      EXPECT_EQ(found[i], expected[i]) << cell;
    }
  }
}

// scans.csv and scans.json of one run hold the same keys and the same
// values (both from LocalizationResultTable).
void ExpectCsvEqualsJson(const std::string& out) {
  const auto rows = ReadCsvRows(out + "/scans.csv");
  std::ifstream json_file(out + "/scans.json");
  Json json;
  json_file >> json;
  EXPECT_EQ(json["tool"], "mlndt_localize");
  const Json& scans = json["scans"];
  ASSERT_EQ(rows.size(), scans.size());
  for (size_t k = 0; k < rows.size(); ++k) {
    SCOPED_TRACE("scan " + std::to_string(k));
    EXPECT_FALSE(scans[k]["registration"].contains("trace"));
    EXPECT_TRUE(scans[k]["registration"].contains("covariance"));
    std::vector<std::pair<std::string, Json>> leaves;
    FlattenJson(scans[k], "", &leaves);
    ASSERT_EQ(rows[k].size(), leaves.size());
    std::map<std::string, Json> by_name(leaves.begin(), leaves.end());
    for (const auto& [name, cell] : rows[k]) {
      SCOPED_TRACE(name);
      ASSERT_EQ(by_name.count(name), 1u);
      ExpectSameValue(cell, by_name.at(name));
    }
  }
}

// Every scan of `trajectory` within 0.2 m and 1 degree of `reference`.
void ExpectWithinReference(const std::vector<Isometry3d>& trajectory,
                           const std::vector<Isometry3d>& reference) {
  ASSERT_EQ(trajectory.size(), reference.size());
  for (size_t k = 0; k < trajectory.size(); ++k) {
    const double t = TranslationErrorM(reference[k], trajectory[k]);
    const double r = RotationErrorRad(reference[k], trajectory[k]) * kRadToDeg;
    EXPECT_LT(t, 0.2) << "scan " << k;
    EXPECT_LT(r, 1.0) << "scan " << k;
  }
}

// The acceptance run: all 8 scans, 10 m and 45 degrees off.
TEST(MlndtLocalize, KittiScansFromTenMetresAndFortyFiveDegreesOff) {
  const std::string dir = TestDir();
  const KittiMap kitti = BuildKittiMap(dir);
  const std::string out = dir + "/out";
  const bool plots = GnuplotInstalled();
  const ToolRun run = testing::RunTool(
      "mlndt_localize",
      "--map=" + Quote(kitti.map) + " --scans=" + Quote(KittiPcd()) +
          " --initial_guess=10,0,0,0,0,45 --output_dir=" + Quote(out) +
          (plots ? "" : " --plots=false"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find("mlndt_localize 8/8 000007.pcd CONVERGENCE"),
            std::string::npos)
      << run.err;  // Progress.
  EXPECT_NE(run.out.find("scans: 8, usable 8"), std::string::npos) << run.out;

  const std::vector<Isometry3d> reference = ReadPoses(kitti.poses);
  const std::vector<Isometry3d> estimate =
      ReadPoses(out + "/trajectory_kitti.txt");
  ExpectWithinReference(estimate, reference);
  // The first guess really is 10 m and 45 degrees from the first pose.
  const Isometry3d first_guess =
      PoseVectorToIsometry(PoseVectorFromDegrees(10, 0, 0, 0, 0, 45));
  EXPECT_NEAR(TranslationErrorM(reference[0], first_guess), 10.0, 0.05);
  EXPECT_NEAR(
      RotationErrorRad(reference[0], first_guess) * kRadToDeg, 45.0, 0.5);

  // TUM: the same poses at times 0, 1, 2, ...
  Trajectory tum;
  std::string error;
  ASSERT_TRUE(ReadTrajectory(
      out + "/trajectory_tum.txt", TrajectoryFormat::TUM, &tum, &error))
      << error;
  ASSERT_EQ(tum.size(), 8u);
  for (size_t k = 0; k < tum.size(); ++k) {
    EXPECT_EQ(tum.timestamp_s(k), static_cast<double>(k));
    EXPECT_TRUE(tum.world_from_sensor(k).isApprox(estimate[k], 1e-9));
  }

  // scans.csv: a row per scan with verdict, quality, pose and times.
  const auto rows = ReadCsv(out + "/scans.csv");
  ASSERT_EQ(rows.size(), 8u);
  for (size_t k = 0; k < rows.size(); ++k) {
    SCOPED_TRACE("row " + std::to_string(k));
    const auto& row = rows[k];
    EXPECT_EQ(row.at("index"), std::to_string(k));
    EXPECT_EQ(row.at("file"), "00000" + std::to_string(k) + ".pcd");
    EXPECT_EQ(row.at("registration.termination_type"), "CONVERGENCE");
    EXPECT_EQ(row.at("usable"), "true");
    EXPECT_GT(std::stod(row.at("registration.quality.inlier_fraction")), 0.9);
    EXPECT_GT(std::stod(row.at("registration.quality.own_cell_fraction")), 0.9);
    EXPECT_GT(std::stod(row.at("registration.total_time_s")), 0.0);
    EXPECT_GE(std::stod(row.at("load_time_s")), 0.0);
    // The pose vector's first number is tx, to 17 digits.
    EXPECT_NEAR(std::stod(row.at("map_from_scan_xi")),
                estimate[k].translation().x(),
                1e-9);
  }
  ExpectCsvEqualsJson(out);
  // Scan 0 was corrected by the whole offset.
  EXPECT_NEAR(std::stod(rows[0].at("correction_m")), 10.0, 0.05);
  EXPECT_NEAR(std::stod(rows[0].at("correction_rad")) * kRadToDeg, 45.0, 0.5);

  std::ifstream json_file(out + "/summary.json");
  Json summary;
  json_file >> summary;
  EXPECT_EQ(summary["scans"].get<int>(), 8);
  EXPECT_EQ(summary["terminations"]["CONVERGENCE"].get<int>(), 8);
  EXPECT_EQ(summary["motion_model"].get<std::string>(), "CONSTANT_VELOCITY");
  EXPECT_EQ(summary["schema_version"], 2);
  EXPECT_EQ(summary["tool"], "mlndt_localize");
  EXPECT_EQ(summary["first_guess"]["rotation_deg"][2].get<double>(), 45.0);
  EXPECT_GT(summary["time_ms_stats"]["registration"]["mean"].get<double>(),
            0.0);
  EXPECT_GT(summary["time_ms"]["total"].get<double>(),
            summary["time_ms"]["map_load"].get<double>());
  EXPECT_EQ(fs::exists(out + "/trajectory_xy.png"), plots);
}

// The first pose from a pose file (its first line) with the constant-pose
// model; the scans from a list of three.
TEST(MlndtLocalize, FirstPoseFromAFileAndAScanList) {
  const std::string dir = TestDir();
  const KittiMap kitti = BuildKittiMap(dir);
  {
    std::ofstream list(dir + "/scans.txt");
    for (int k = 0; k < 3; ++k) {
      list << KittiPcd() << "/00000" << k << ".pcd\n";
    }
  }
  const std::string out = dir + "/out";
  const ToolRun run = testing::RunTool(
      "mlndt_localize",
      "--map=" + Quote(kitti.map) + " --scan_list=" +
          Quote(dir + "/scans.txt") + " --initial_poses=" + Quote(kitti.poses) +
          " --motion_model=constant_pose --plots=false --output_dir=" +
          Quote(out));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  std::vector<Isometry3d> reference = ReadPoses(kitti.poses);
  reference.resize(3);
  ExpectWithinReference(ReadPoses(out + "/trajectory_kitti.txt"), reference);
  // From the reference itself, scan 0 barely moves.
  const auto rows = ReadCsv(out + "/scans.csv");
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_LT(std::stod(rows[0].at("correction_m")), 0.05);

  // The same from a 12-number matrix, two scans.
  const ToolRun matrix = testing::RunTool(
      "mlndt_localize",
      "--map=" + Quote(kitti.map) + " --scans=" + Quote(KittiPcd()) +
          " --max_scans=2 --initial_matrix=1,0,0,0.5,0,1,0,0,0,0,1,0 "
          "--plots=false --output_dir=" +
          Quote(out));
  ASSERT_EQ(matrix.exit_code, 0) << matrix.err;
  reference.resize(2);
  ExpectWithinReference(ReadPoses(out + "/trajectory_kitti.txt"), reference);
}

// Plots requested without gnuplot: exit 1, saying so, with the other
// outputs written.
TEST(MlndtLocalize, MissingGnuplotFailsAfterWritingTheRest) {
  const std::string dir = TestDir();
  const KittiMap kitti = BuildKittiMap(dir);
  const std::string out = dir + "/out";
  const ToolRun run = testing::RunTool(
      "mlndt_localize",
      "--map=" + Quote(kitti.map) + " --scans=" + Quote(KittiPcd()) +
          " --max_scans=1 --gnuplot=/nonexistent/gnuplot --output_dir=" +
          Quote(out));
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("gnuplot ('/nonexistent/gnuplot') not found"),
            std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("--plots=false"), std::string::npos);
  EXPECT_TRUE(fs::exists(out + "/trajectory_kitti.txt"));
  EXPECT_TRUE(fs::exists(out + "/scans.csv"));
  EXPECT_FALSE(fs::exists(out + "/trajectory_xy.png"));
}

// Every misconfiguration: exit code 2, a message naming the flag, and no
// work (no output folder).
TEST(MlndtLocalize, RefusesBadFlags) {
  const std::string dir = TestDir();
  const KittiMap kitti = BuildKittiMap(dir);
  const std::string out = dir + "/never";
  const std::string base = "--map=" + Quote(kitti.map) +
                           " --scans=" + Quote(KittiPcd()) +
                           " --output_dir=" + Quote(out);
  struct Case {
    std::string args;
    std::string message;
  } cases[] = {
      {"", "give --map=FILE, --scans=DIR"},
      {"--map=" + Quote(kitti.map) + " --output_dir=" + Quote(out),
       "give --map=FILE, --scans=DIR"},
      {"--scans=" + Quote(KittiPcd()) + " --output_dir=" + Quote(out),
       "give --map=FILE"},
      {"--map=/nonexistent.mlndt --scans=" + Quote(KittiPcd()) +
           " --output_dir=" + Quote(out),
       "--map=/nonexistent.mlndt: no such file"},
      {"--map=" + Quote(kitti.map) + " --scans=" + Quote(KittiPcd()) +
           " --output_dir=" + Quote(kitti.map + "/out"),
       "--output_dir=" + kitti.map + "/out: cannot create the folder"},
      {base + " --max_scans=-1", "--max_scans must be >= 0"},
      {base + " --start_layer=9",
       "--start_layer=9 is out of range: the map has"},
      {base + " --plot_max_cells=-1", "--plot_max_cells must be >= 0"},
      {base + " --initial_guess=1,2", "--initial_guess=1,2: expected 6"},
      {base + " --initial_guess=0,0,0,0,0,0 --initial_matrix=1",
       "give one of --initial_guess, --initial_matrix and --initial_poses"},
      {base +
           " --initial_guess=0,0,0,0,0,0 --initial_poses=" + Quote(kitti.poses),
       "give one of"},
      {base + " --initial_matrix=1,2,3", "--initial_matrix needs 12"},
      {base + " --initial_matrix=2,0,0,0,0,1,0,0,0,0,1,0",
       "--initial_matrix: the 3x3 part is not a rotation"},
      {base + " --initial_poses=/nonexistent.txt",
       "--initial_poses: /nonexistent.txt"},
      {base + " --initial_poses=" + Quote(kitti.poses) +
           " --initial_poses_format=csv",
       "--initial_poses_format=csv: expected auto, kitti or tum"},
      {base + " --poses_are_camera --calib=" +
           Quote(testing::BundledDataPath("kitti/calib.txt")),
       "--calib converts pose files; give it with --initial_poses"},
      {base + " --initial_poses=" + Quote(kitti.poses) + " --poses_are_camera",
       "--poses_are_camera needs --calib=calib.txt"},
      {base + " --motion_model=kalman",
       "--motion_model=kalman: expected constant_velocity or constant_pose"},
      {base + " --finest_cell_size_m=1",
       "--finest_cell_size_m does not apply to mlndt_localize"},
      {base + " --min_points_per_cell=6",
       "--min_points_per_cell does not apply to mlndt_localize"},
      {base + " --division_constant=27", "--division_constant does not apply"},
      {base + " --method=ndt", "this tool runs ML-NDT only"},
      {base + " --backend=simplex", "--backend=simplex: expected ceres"},
      {base + " --num_threads=0", "threads"},
      {base + " --scan_list=x.txt",
       "give --scans=DIR or --scan_list=FILE, not both"},
      {"--map=" + Quote(kitti.map) +
           " --scans=/nonexistent --output_dir=" + Quote(out),
       "--scans: /nonexistent"},
      {base + " stray", "the data 'stray' is given as an argument and as"},
      {base + " stray more", "unexpected argument 'stray'"},
  };
  for (const Case& c : cases) {
    const ToolRun run = testing::RunTool("mlndt_localize", c.args);
    EXPECT_EQ(run.exit_code, 2) << c.args;
    EXPECT_NE(run.err.find(c.message), std::string::npos)
        << c.args << "\nstderr: " << run.err;
    EXPECT_FALSE(fs::exists(out)) << c.args;
  }
}

// Issue 27 item 12: --map naming a folder says it is one.
TEST(MlndtLocalize, MapThatIsAFolderIsCalledOne) {
  const std::string dir = TestDir();
  const ToolRun run =
      testing::RunTool("mlndt_localize",
                       "--map=" + Quote(dir) + " --scans=" + Quote(KittiPcd()) +
                           " --output_dir=" + Quote(dir + "/out"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--map=" + dir + ": it is a directory"),
            std::string::npos)
      << run.err;
  EXPECT_EQ(run.err.find("no such file"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(dir + "/out"));
}

// Issue 27 item 14: --help lists only the flags mlndt_localize accepts;
// the map's flags and conventional NDT's are refused, not listed.
TEST(MlndtLocalize, HelpListsOnlyTheFlagsItAccepts) {
  const ToolRun help = testing::RunTool("mlndt_localize", "--help");
  ASSERT_EQ(help.exit_code, 0);
  for (const char* refused : {"finest_cell_size_m",
                              "num_layers",
                              "division_constant",
                              "min_points_per_cell",
                              "min_eigenvalue_m2",
                              "min_eigenvalue_ratio",
                              "coarse_weighting",
                              "ndt_cell_size_m",
                              "ndt_outlier_ratio",
                              "ndt_neighbors",
                              "ndt_max_iterations",
                              "ndt_max_step_norm"}) {
    EXPECT_EQ(help.out.find(std::string("  --") + refused + "="),
              std::string::npos)
        << refused;
  }
  for (const char* accepted : {"map",
                               "initial_guess",
                               "backend",
                               "quality_check",
                               "min_range_m",
                               "num_threads",
                               "calib"}) {
    EXPECT_NE(help.out.find(std::string("  --") + accepted + "="),
              std::string::npos)
        << accepted;
  }
  // The map fixes the coarse layers' weighting too.
  const std::string dir = TestDir();
  const KittiMap kitti = BuildKittiMap(dir);
  const ToolRun run = testing::RunTool(
      "mlndt_localize",
      "--map=" + Quote(kitti.map) + " --scans=" + Quote(KittiPcd()) +
          " --coarse_weighting=points --output_dir=" + Quote(dir + "/out"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--coarse_weighting does not apply to mlndt_localize"),
            std::string::npos)
      << run.err;
  EXPECT_FALSE(fs::exists(dir + "/out"));
}

}  // namespace
}  // namespace mlndt

namespace mlndt {
namespace {

// Issue 27 item 1: scans whose result fails the quality check (LOW_QUALITY,
// here forced by demanding every point be an inlier) are not usable: the
// summary counts them by verdict, their pose is the prediction, and the
// tool exits 1 (it printed "usable 3" and exited 0 before).
TEST(MlndtLocalize, LowQualityScansAreCountedAndExitOne) {
  const std::string dir = TestDir();
  const KittiMap kitti = BuildKittiMap(dir);
  const std::string out = dir + "/out";
  const ToolRun run = testing::RunTool(
      "mlndt_localize",
      "--map=" + Quote(kitti.map) + " --scans=" + Quote(KittiPcd()) +
          " --max_scans=3 --min_inlier_fraction=1 --yaw_seeds_deg= "
          "--plots=false --output_dir=" +
          Quote(out));
  EXPECT_EQ(run.exit_code, 1) << run.out << run.err;
  EXPECT_NE(run.out.find("scans: 3, usable 0 (CONVERGENCE 0, NO_CONVERGENCE "
                         "0, LOW_QUALITY 3, DEGENERATE 0, FAILURE 0)"),
            std::string::npos)
      << run.out;
  EXPECT_NE(run.err.find("3 of 3 scans have no usable pose"), std::string::npos)
      << run.err;
  std::ifstream json_file(out + "/summary.json");
  Json summary;
  json_file >> summary;
  const Json& verdicts = summary["terminations"];
  EXPECT_EQ(verdicts["LOW_QUALITY"].get<int>(), 3);
  int sum = 0;
  for (const char* key : {"CONVERGENCE",
                          "NO_CONVERGENCE",
                          "LOW_QUALITY",
                          "DEGENERATE",
                          "FAILURE"}) {
    ASSERT_TRUE(verdicts.contains(key)) << key;
    sum += verdicts[key].get<int>();
  }
  EXPECT_EQ(sum, 3);
  EXPECT_EQ(summary["usable"].get<int>(), 0);
  EXPECT_EQ(summary["unusable"].get<int>(), 3);
  // Dead reckoning: no correction of any prediction is kept.
  for (const auto& row : ReadCsv(out + "/scans.csv")) {
    EXPECT_EQ(row.at("registration.termination_type"), "LOW_QUALITY");
    EXPECT_EQ(std::stod(row.at("correction_m")), 0.0);
  }
}

}  // namespace
}  // namespace mlndt
