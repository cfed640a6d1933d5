// Runs the built mlndt_sequence binary (tests/testing/test_data.h ToolPath)
// on the bundled KITTI frames and on a synthetic sequence, and checks its
// files, the consistency of summary.json with pairs.csv, the accuracy and
// the exit codes.
//
// Data note: on the bundled KITTI frames the scans' geometry fits about 0.8
// times the ground-truth translation, so even a perfect matcher ends about
// 0.17 m per frame of motion from the ground truth. Step-1 pairs pass the
// strict 0.2 m rule; "near-zero error from the ground-truth start" is
// therefore checked on a synthetic sequence whose ground truth is exact.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "mlndt/cloud/io.h"
#include "mlndt/cloud/pose_io.h"
#include "mlndt/common/pose.h"
#include "tests/testing/run_tool.h"
#include "tests/testing/scratch_dir.h"
#include "tests/testing/synthetic_scene.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

using testing::ToolRun;
const auto& Quote = testing::ShellQuote;
const auto& ReadFile = testing::ReadWholeFile;

namespace fs = std::filesystem;

// A fresh folder under the test temp dir, named after the current test.
std::string TestDir(const std::string& suffix = "") {
  const std::string dir = testing::ScratchPath("out" + suffix);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// Runs mlndt_sequence with `args` (already quoted where needed).
ToolRun RunSequence(const std::string& args) {
  return testing::RunTool("mlndt_sequence", args);
}

bool GnuplotInstalled() {
  return std::system("gnuplot --version >/dev/null 2>&1") == 0;
}

// ---- A minimal JSON reader: numbers, strings, booleans and null of nested
// objects, flattened to "a.b.c" keys (arrays are skipped). -------------------

class FlatJson {
 public:
  explicit FlatJson(const std::string& text) : text_(text) {
    SkipSpace();
    ok_ = ParseValue("") && (SkipSpace(), pos_ == text_.size());
  }
  bool ok() const { return ok_; }
  bool Has(const std::string& key) const { return values_.count(key) > 0; }
  double Number(const std::string& key) const {
    auto it = values_.find(key);
    return it == values_.end() ? std::nan("")
                               : std::strtod(it->second.c_str(), nullptr);
  }
  std::string String(const std::string& key) const {
    auto it = values_.find(key);
    return it == values_.end() ? "" : it->second;
  }

 private:
  void SkipSpace() {
    while (pos_ < text_.size() &&
           std::isspace(static_cast<unsigned char>(text_[pos_])))
      ++pos_;
  }
  bool ParseString(std::string* out) {
    if (text_[pos_] != '"') return false;
    ++pos_;
    while (pos_ < text_.size() && text_[pos_] != '"') {
      if (text_[pos_] == '\\') ++pos_;
      *out += text_[pos_++];
    }
    ++pos_;
    return pos_ <= text_.size();
  }
  bool ParseValue(const std::string& key) {
    SkipSpace();
    if (pos_ >= text_.size()) return false;
    const char c = text_[pos_];
    if (c == '{') {
      ++pos_;
      SkipSpace();
      if (text_[pos_] == '}') return ++pos_, true;
      while (true) {
        SkipSpace();
        std::string name;
        if (!ParseString(&name)) return false;
        SkipSpace();
        if (text_[pos_++] != ':') return false;
        if (!ParseValue(key.empty() ? name : key + "." + name)) return false;
        SkipSpace();
        if (text_[pos_] == ',') {
          ++pos_;
          continue;
        }
        return text_[pos_++] == '}';
      }
    }
    if (c == '[') {
      int depth = 0;
      do {
        if (text_[pos_] == '[') ++depth;
        if (text_[pos_] == ']') --depth;
        ++pos_;
      } while (depth > 0 && pos_ < text_.size());
      return depth == 0;
    }
    if (c == '"') {
      std::string value;
      if (!ParseString(&value)) return false;
      values_[key] = value;
      return true;
    }
    const size_t begin = pos_;
    while (pos_ < text_.size() &&
           std::string(",}] \n\t").find(text_[pos_]) == std::string::npos) {
      ++pos_;
    }
    values_[key] = text_.substr(begin, pos_ - begin);
    return pos_ > begin;
  }

  std::string text_;
  size_t pos_ = 0;
  bool ok_ = false;
  std::map<std::string, std::string> values_;
};

// pairs.csv as rows of named fields.
std::vector<std::map<std::string, std::string>> ReadCsv(
    const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::vector<std::string> header;
  std::vector<std::map<std::string, std::string>> rows;
  while (std::getline(in, line)) {
    std::vector<std::string> fields;
    std::stringstream stream(line);
    std::string field;
    while (std::getline(stream, field, ',')) fields.push_back(field);
    if (!line.empty() && line.back() == ',') fields.push_back("");
    if (header.empty()) {
      header = fields;
      continue;
    }
    EXPECT_EQ(fields.size(), header.size()) << line;
    std::map<std::string, std::string> row;
    for (size_t k = 0; k < header.size() && k < fields.size(); ++k)
      row[header[k]] = fields[k];
    rows.push_back(row);
  }
  return rows;
}

double Field(const std::map<std::string, std::string>& row,
             const std::string& name) {
  auto it = row.find(name);
  EXPECT_NE(it, row.end()) << name;
  return it == row.end() ? std::nan("")
                         : std::strtod(it->second.c_str(), nullptr);
}

size_t CountLines(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  size_t n = 0;
  while (std::getline(in, line)) n += !line.empty();
  return n;
}

// Recomputation of the summary statistics (the documented definitions).
struct Recomputed {
  double mean = 0, std = 0, max = 0, median = 0, p95 = 0;
};
Recomputed Recompute(std::vector<double> v) {
  Recomputed r;
  if (v.empty()) return r;
  std::sort(v.begin(), v.end());
  for (double x : v) r.mean += x;
  r.mean /= v.size();
  for (double x : v) r.std += (x - r.mean) * (x - r.mean);
  r.std = v.size() > 1 ? std::sqrt(r.std / (v.size() - 1)) : 0.0;
  r.max = v.back();
  const size_t n = v.size();
  r.median = n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
  r.p95 = v[std::max<size_t>(static_cast<size_t>(std::ceil(0.95 * n)), 1) - 1];
  return r;
}

void ExpectClose(double summary, double recomputed, const std::string& what) {
  EXPECT_NEAR(summary, recomputed, 1e-6 * std::max(1.0, std::abs(recomputed)))
      << what;
}

std::string KittiArgs(const std::string& output_dir) {
  return "--scans=" + Quote(testing::BundledDataPath("kitti/pcd")) +
         " --gt_poses=" +
         Quote(testing::BundledDataPath("kitti/poses_velo.txt")) +
         " --output_dir=" + Quote(output_dir);
}

TEST(MlndtSequence, KittiStepOneFromZero) {
  const std::string dir = TestDir();
  const bool plots = GnuplotInstalled();
  const ToolRun run = RunSequence(KittiArgs(dir) + " --step=1 --init=zero" +
                                  (plots ? "" : " --plots=false"));
  ASSERT_EQ(run.exit_code, 0) << run.err << run.out;
  for (const char* file : {"pairs.csv",
                           "summary.json",
                           "trace.csv",
                           "trajectory_kitti.txt",
                           "gt_trajectory_kitti.txt"}) {
    EXPECT_TRUE(fs::is_regular_file(dir + "/" + file)) << file;
  }
  if (plots) {
    for (const char* png : {"errors_translation.png",
                            "errors_rotation.png",
                            "trajectory_xy.png",
                            "score_vs_iteration.png"}) {
      EXPECT_GT(fs::file_size(dir + "/" + png), 1000u) << png;
    }
  }
  // One progress line per pair when stderr is not a terminal.
  EXPECT_NE(run.err.find("7/7 pair 6->7"), std::string::npos) << run.err;

  const std::vector<std::map<std::string, std::string>> rows =
      ReadCsv(dir + "/pairs.csv");
  ASSERT_EQ(rows.size(), 7u);
  const FlatJson summary(ReadFile(dir + "/summary.json"));
  ASSERT_TRUE(summary.ok()) << ReadFile(dir + "/summary.json");
  EXPECT_EQ(summary.Number("pairs"), 7.0);
  EXPECT_EQ(summary.Number("scans"), 8.0);

  // summary.json equals what pairs.csv gives.
  double successes = 0, strict = 0;
  std::vector<double> time, iterations;
  std::map<std::string, std::vector<double>> errors;
  const std::map<std::string, std::string> columns = {
      {"tx_cm", "err_tx_cm"},
      {"ty_cm", "err_ty_cm"},
      {"tz_cm", "err_tz_cm"},
      {"alpha_deg", "err_alpha_deg"},
      {"beta_deg", "err_beta_deg"},
      {"gamma_deg", "err_gamma_deg"},
      {"translation_cm", "translation_error_cm"},
      {"rotation_deg", "rotation_error_deg"}};
  for (size_t k = 0; k < rows.size(); ++k) {
    const auto& row = rows[k];
    EXPECT_EQ(Field(row, "reference"), double(k));
    EXPECT_EQ(Field(row, "input"), double(k + 1));
    successes += Field(row, "success");
    strict += Field(row, "strict_success");
    time.push_back(Field(row, "time_total_ms"));
    iterations.push_back(Field(row, "iterations"));
    for (const auto& [name, column] : columns)
      errors[name].push_back(std::abs(Field(row, column)));
    // The norms agree with the components.
    const double tx = Field(row, "err_tx_cm"), ty = Field(row, "err_ty_cm"),
                 tz = Field(row, "err_tz_cm");
    EXPECT_NEAR(std::sqrt(tx * tx + ty * ty + tz * tz),
                Field(row, "translation_error_cm"),
                1e-6);
    EXPECT_EQ(Field(row, "success"),
              Field(row, "translation_error_cm") < 50.0 ? 1.0 : 0.0);
    EXPECT_EQ(Field(row, "strict_success"),
              Field(row, "translation_error_cm") < 20.0 &&
                      Field(row, "rotation_error_deg") < 1.0
                  ? 1.0
                  : 0.0);
    EXPECT_LE(Field(row, "time_map_ms") + Field(row, "time_sampling_ms") +
                  Field(row, "time_solve_ms"),
              Field(row, "time_total_ms") + 1e-6);
  }
  ExpectClose(summary.Number("success_rate_percent"),
              100.0 * successes / rows.size(),
              "success");
  ExpectClose(summary.Number("strict_success_rate_percent"),
              100.0 * strict / rows.size(),
              "strict");
  for (const auto& [name, values] : errors) {
    const Recomputed r = Recompute(values);
    ExpectClose(
        summary.Number("errors." + name + ".mean"), r.mean, name + " mean");
    ExpectClose(
        summary.Number("errors." + name + ".std"), r.std, name + " std");
    ExpectClose(
        summary.Number("errors." + name + ".max"), r.max, name + " max");
  }
  const Recomputed t = Recompute(time);
  ExpectClose(summary.Number("time_ms_stats.pair.mean"), t.mean, "time mean");
  ExpectClose(
      summary.Number("time_ms_stats.pair.median"), t.median, "time median");
  ExpectClose(summary.Number("time_ms_stats.pair.p95"), t.p95, "time p95");
  ExpectClose(summary.Number("time_ms_stats.pair.max"), t.max, "time max");
  ExpectClose(summary.Number("mean_iterations"),
              Recompute(iterations).mean,
              "iterations");

  // The requirement: >= 95 % strict successes on consecutive pairs.
  EXPECT_GE(summary.Number("strict_success_rate_percent"), 95.0);

  // Trajectories: 8 poses, the first the identity, GT = the velodyne poses.
  ASSERT_EQ(CountLines(dir + "/trajectory_kitti.txt"), 8u);
  ASSERT_EQ(CountLines(dir + "/gt_trajectory_kitti.txt"), 8u);
  std::vector<Eigen::Isometry3d> estimate, truth, velo;
  std::string error;
  ASSERT_TRUE(ReadKittiPoses(dir + "/trajectory_kitti.txt", &estimate, &error))
      << error;
  ASSERT_TRUE(ReadKittiPoses(dir + "/gt_trajectory_kitti.txt", &truth, &error))
      << error;
  ASSERT_TRUE(ReadKittiPoses(
      testing::BundledDataPath("kitti/poses_velo.txt"), &velo, &error));
  EXPECT_TRUE(estimate[0].isApprox(Eigen::Isometry3d::Identity(), 1e-12));
  for (size_t k = 0; k < 8; ++k) {
    EXPECT_LT(TranslationErrorM(truth[k], velo[0].inverse() * velo[k]), 1e-4)
        << k;
  }
  // Chained estimate: the data's ~0.8x scale leaves ~0.17 m per frame.
  EXPECT_LT(TranslationErrorM(estimate[7], truth[7]), 0.25 * 7);
}

// Writes a synthetic sequence with exact ground truth: 4 scans of one
// street scene seen from poses 1.5 m and 3 deg of yaw apart, plus poses.txt
// in the same folder (which must not be taken for a scan).
std::string WriteSyntheticSequence(const std::string& dir) {
  std::vector<Eigen::Isometry3d> poses;
  for (int k = 0; k < 4; ++k) {
    Eigen::Isometry3d world_from_scan = PoseVectorToIsometry(
        PoseVectorFromDegrees(1.5 * k, 0.2 * k, 0.02 * k, 0.0, 0.0, 3.0 * k));
    poses.push_back(world_from_scan);
    const PointCloud world = testing::StreetScene(40000, 0.01, 100 + k);
    std::string error;
    EXPECT_TRUE(
        WritePointCloud(dir + "/scan_" + std::to_string(k) + ".pcd",
                        TransformCloud(world_from_scan.inverse(), world),
                        &error))
        << error;
  }
  std::string error;
  EXPECT_TRUE(WriteKittiPoses(dir + "/poses.txt", poses, &error)) << error;
  return dir + "/poses.txt";
}

TEST(MlndtSequence, GroundTruthInitGivesNearZeroErrorQuickly) {
  const std::string data = TestDir("_data");
  const std::string poses = WriteSyntheticSequence(data);
  const std::string dir = TestDir();
  const ToolRun run =
      RunSequence("--scans=" + Quote(data) + " --gt_poses=" + Quote(poses) +
                  " --output_dir=" + Quote(dir) +
                  " --init=gt_fraction:1.0 --start_layer=0 --plots=false");
  ASSERT_EQ(run.exit_code, 0) << run.err << run.out;
  const FlatJson summary(ReadFile(dir + "/summary.json"));
  ASSERT_TRUE(summary.ok());
  EXPECT_EQ(summary.Number("scans"), 4.0);  // poses.txt is not a scan.
  EXPECT_EQ(summary.Number("pairs"), 3.0);
  EXPECT_EQ(summary.Number("strict_success_rate_percent"), 100.0);
  EXPECT_LT(summary.Number("errors.translation_cm.max"), 2.0);
  EXPECT_LT(summary.Number("errors.rotation_deg.max"), 0.1);
  EXPECT_LE(summary.Number("mean_iterations"), 10.0);

  // From zero the same pairs need more iterations (and still succeed).
  const std::string zero_dir = TestDir("_zero");
  const ToolRun zero =
      RunSequence("--scans=" + Quote(data) + " --gt_poses=" + Quote(poses) +
                  " --output_dir=" + Quote(zero_dir) + " --plots=false");
  ASSERT_EQ(zero.exit_code, 0) << zero.err;
  const FlatJson zero_summary(ReadFile(zero_dir + "/summary.json"));
  EXPECT_GT(zero_summary.Number("mean_iterations"),
            summary.Number("mean_iterations"));
  EXPECT_EQ(zero_summary.Number("strict_success_rate_percent"), 100.0);
}

TEST(MlndtSequence, KittiGroundTruthInitStaysAtTheDataOptimum) {
  // On KITTI the optimum itself is ~0.17 m from GT (0.8x scale): a GT start
  // ends there, in few iterations on the last layer.
  const std::string dir = TestDir();
  const ToolRun run =
      RunSequence(KittiArgs(dir) +
                  " --max_scans=4 --init=gt_fraction:1.0 --start_layer=0 "
                  "--plots=false");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const FlatJson summary(ReadFile(dir + "/summary.json"));
  EXPECT_EQ(summary.Number("strict_success_rate_percent"), 100.0);
  EXPECT_LT(summary.Number("errors.translation_cm.max"), 20.0);
  EXPECT_LT(summary.Number("errors.rotation_deg.max"), 0.5);
  EXPECT_LE(summary.Number("mean_iterations"), 30.0);
}

TEST(MlndtSequence, CameraPosesWithCalibMatchVelodynePoses) {
  // Scans, camera poses and calib.txt in one folder: the two text files
  // are not scans; the converted poses equal poses_velo.txt. The 3 scans
  // are the first of the 8-pose run: --max_scans says so (CheckPoseCount).
  const std::string data = TestDir("_data");
  for (int k = 0; k < 3; ++k) {
    const std::string name = "00000" + std::to_string(k) + ".pcd";
    fs::create_symlink(testing::BundledDataPath("kitti/pcd/" + name),
                       data + "/" + name);
  }
  fs::copy_file(testing::BundledDataPath("kitti/poses_cam0.txt"),
                data + "/poses_cam0.txt");
  fs::copy_file(testing::BundledDataPath("kitti/calib.txt"),
                data + "/calib.txt");
  const std::string dir = TestDir();
  const ToolRun run =
      RunSequence("--scans=" + Quote(data) +
                  " --gt_poses=" + Quote(data + "/poses_cam0.txt") +
                  " --poses_are_camera --calib=" + Quote(data + "/calib.txt") +
                  " --output_dir=" + Quote(dir) +
                  " --backend=lm --plots=false" + " --max_scans=3");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const FlatJson summary(ReadFile(dir + "/summary.json"));
  EXPECT_EQ(summary.Number("scans"), 3.0);
  std::vector<Eigen::Isometry3d> truth, velo;
  std::string error;
  ASSERT_TRUE(ReadKittiPoses(dir + "/gt_trajectory_kitti.txt", &truth, &error))
      << error;
  ASSERT_TRUE(ReadKittiPoses(
      testing::BundledDataPath("kitti/poses_velo.txt"), &velo, &error));
  ASSERT_EQ(truth.size(), 3u);
  for (size_t k = 0; k < 3; ++k) {
    EXPECT_LT(TranslationErrorM(truth[k], velo[0].inverse() * velo[k]), 1e-4)
        << k;
    EXPECT_LT(RotationErrorRad(truth[k], velo[0].inverse() * velo[k]), 1e-5)
        << k;
  }
}

TEST(MlndtSequence, AdaptiveStartLayerFollowsTheRunningFailRate) {
  const std::string dir = TestDir();
  const ToolRun run =
      RunSequence(KittiArgs(dir) +
                  " --max_scans=6 --step=2 --init=constant_velocity "
                  "--adaptive_start_layer --backend=lm --plots=false");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::vector<std::map<std::string, std::string>> rows =
      ReadCsv(dir + "/pairs.csv");
  ASSERT_EQ(rows.size(), 4u);
  const double n = Field(rows[0], "num_layers");
  EXPECT_EQ(Field(rows[0], "start_layer"), n);  // Starts on the last layer.
  EXPECT_EQ(Field(rows[0], "running_fail_rate"), 0.0);
  double failed = 0;
  for (size_t p = 0; p < rows.size(); ++p) {
    const double rate = p == 0 ? 0.0 : failed / p;
    EXPECT_NEAR(Field(rows[p], "running_fail_rate"), rate, 1e-9) << p;
    const int coarser = (rate > 0.05) + (rate > 0.2);
    EXPECT_EQ(Field(rows[p], "start_layer"), std::max(1.0, n - coarser)) << p;
    const bool check_failed = Field(rows[p], "guess_deviation_m") > 1.0 ||
                              Field(rows[p], "guess_deviation_deg") > 15.0 ||
                              rows[p].at("termination") == "FAILURE";
    EXPECT_EQ(Field(rows[p], "guess_check_failed"), check_failed ? 1.0 : 0.0)
        << p;
    failed += check_failed;
  }
  // The first step-2 pair moves ~1.7 m from a zero guess: a "failure" by the
  // rule, so the next pair starts coarser.
  EXPECT_EQ(Field(rows[0], "guess_check_failed"), 1.0);
  EXPECT_LT(Field(rows[1], "start_layer"), n);
  const FlatJson summary(ReadFile(dir + "/summary.json"));
  EXPECT_EQ(summary.String("adaptive_start_layer"), "true");
}

// An --output_dir that cannot be created is refused before any pair is
// registered.
TEST(MlndtSequence, UnwritableOutputFolderIsRefusedBeforeAnyWork) {
  const std::string dir = TestDir();
  { std::ofstream file(dir + "/file"); }
  const std::string out = dir + "/file/out";
  const ToolRun run = RunSequence(KittiArgs(out));
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find("--output_dir=" + out + ": cannot create the folder"),
            std::string::npos)
      << run.err;
  EXPECT_EQ(run.err.find("pair 0->1"), std::string::npos) << run.err;
}

TEST(MlndtSequence, BadFlagsExitTwo) {
  const std::string dir = TestDir();
  const std::string kitti = KittiArgs(dir);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--output_dir=" + Quote(dir), "Usage"},
      {kitti + " --step=0", "--step"},
      {kitti + " --finest_cell_size_m=0 --num_layers=3 --start_layer=5",
       "--start_layer=5 is out of range"},
      {kitti + " --poses_are_camera", "--poses_are_camera needs --calib"},
      {kitti + " --calib=" + Quote(testing::BundledDataPath("kitti/calib.txt")),
       "give --poses_are_camera with it"},
      {kitti + " --step=8", "too few"},
      {kitti + " --init=bogus", "--init=bogus"},
      {kitti + " --init=gt_fraction:x", "gt_fraction"},
      {kitti + " --init=poses:/nonexistent/poses.txt",
       "/nonexistent/poses.txt"},
      {kitti + " --method=ndt --adaptive_start_layer", "adaptive"},
      {kitti + " --adaptive_fail_rate_thresholds=0.5,0.1",
       "adaptive_fail_rate_thresholds"},
      {kitti + " --sampling=bogus", "--sampling"},
      {"--scans=/nonexistent --output_dir=" + Quote(dir), "/nonexistent"},
      {"--scans=" + Quote(testing::BundledDataPath("kitti/pcd")) +
           " --gt_poses=/nonexistent.txt --output_dir=" + Quote(dir),
       "/nonexistent.txt"},
      {"--scans=" + Quote(testing::BundledDataPath("kitti/pcd")) +
           " --init=gt_fraction:0.5 --output_dir=" + Quote(dir),
       "gt_poses"},
      {kitti + " --no_such_flag", "no_such_flag"},
      {kitti + " stray_argument", "stray_argument"},
  };
  for (const auto& [args, message] : cases) {
    const ToolRun run = RunSequence(args);
    EXPECT_EQ(run.exit_code, 2) << args << "\n" << run.err;
    EXPECT_NE(run.err.find(message), std::string::npos) << args << "\n"
                                                        << run.err;
  }
}

TEST(MlndtSequence, MissingGnuplotExitsOneUnlessPlotsAreOff) {
  const std::string dir = TestDir();
  const std::string args = KittiArgs(dir) + " --max_scans=2 --backend=lm";
  const ToolRun run = RunSequence(args + " --gnuplot=/nonexistent/gnuplot");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("gnuplot"), std::string::npos) << run.err;
  EXPECT_TRUE(
      fs::is_regular_file(dir + "/pairs.csv"));  // The data is still written.
  EXPECT_TRUE(fs::is_regular_file(dir + "/summary.json"));
  const ToolRun off =
      RunSequence(args + " --gnuplot=/nonexistent/gnuplot --plots=false");
  EXPECT_EQ(off.exit_code, 0) << off.err;
}

}  // namespace
}  // namespace mlndt

namespace mlndt {
namespace {

// Issue 27 item 2: pairs whose result fails the quality check (forced here
// by demanding every point be an inlier) are counted by verdict, flagged
// where their --init guess stands in for them, and make the tool exit 1 (it
// exited 0 with "registration_failures: 0" before).
TEST(MlndtSequence, UnusablePairsAreCountedFlaggedAndExitOne) {
  const std::string dir = TestDir();
  const ToolRun run =
      RunSequence(KittiArgs(dir) +
                  " --max_scans=3 --min_inlier_fraction=1 --yaw_seeds_deg= "
                  "--plots=false");
  EXPECT_EQ(run.exit_code, 1) << run.out << run.err;
  EXPECT_NE(run.out.find("verdicts: CONVERGENCE 0, NO_CONVERGENCE 0, "
                         "LOW_QUALITY 2, DEGENERATE 0, FAILURE 0; usable 0 "
                         "of 2"),
            std::string::npos)
      << run.out;
  EXPECT_NE(run.err.find("2 of 2 pairs have no usable result (0->1 "
                         "LOW_QUALITY, 1->2 LOW_QUALITY): trajectory_kitti.txt "
                         "chains their --init=zero guess"),
            std::string::npos)
      << run.err;
  const FlatJson summary(ReadFile(dir + "/summary.json"));
  ASSERT_TRUE(summary.ok());
  EXPECT_EQ(summary.Number("terminations.LOW_QUALITY"), 2.0);
  EXPECT_EQ(summary.Number("terminations.CONVERGENCE"), 0.0);
  EXPECT_TRUE(summary.Has("terminations.DEGENERATE"));
  EXPECT_EQ(summary.Number("usable_pairs"), 0.0);
  EXPECT_EQ(summary.Number("unusable_pairs"), 2.0);
  const auto rows = ReadCsv(dir + "/pairs.csv");
  ASSERT_EQ(rows.size(), 2u);
  for (const auto& row : rows) {
    EXPECT_EQ(row.at("termination"), "LOW_QUALITY");
    EXPECT_EQ(row.at("usable"), "0");
    EXPECT_EQ(row.at("estimate_source"), "guess");
  }
}

// Issue 27 item 4: a pose file written with 5 decimals (|R^T R - I| well
// above 1e-6, below 1e-3) is odometry --init=poses:FILE can use, as every
// other pose reader does: no pair fails as "not a rigid transform".
TEST(MlndtSequence, InitPosesAcceptsPosesWrittenWithFewDecimals) {
  const std::string dir = TestDir();
  const std::string odometry = dir + "/odometry_5_decimals.txt";
  double worst = 0.0;
  {
    std::ifstream in(testing::BundledDataPath("kitti/poses_velo.txt"));
    std::ofstream out(odometry);
    std::vector<double> v(12);
    while (in >> v[0]) {
      for (int k = 1; k < 12; ++k) in >> v[static_cast<size_t>(k)];
      Eigen::Matrix3d r;
      for (int k = 0; k < 12; ++k) {
        char text[32];
        std::snprintf(text, sizeof(text), "%.5f", v[static_cast<size_t>(k)]);
        out << (k ? " " : "") << text;
        if (k % 4 != 3) r(k / 4, k % 4) = std::stod(text);
      }
      out << "\n";
      worst = std::max(
          worst, (r.transpose() * r - Eigen::Matrix3d::Identity()).norm());
    }
  }
  ASSERT_GT(worst, 1e-6);  // The old limit of the registration's check.
  ASSERT_LT(worst, 1e-3);
  const std::string out = dir + "/out";
  const ToolRun run = RunSequence(
      KittiArgs(out) + " --max_scans=3 --init=" + "poses:" + Quote(odometry) +
      " --plots=false");
  EXPECT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_EQ(run.err.find("not a rigid transform"), std::string::npos)
      << run.err;
  const auto rows = ReadCsv(out + "/pairs.csv");
  ASSERT_EQ(rows.size(), 2u);
  for (const auto& row : rows) {
    EXPECT_EQ(row.at("termination"), "CONVERGENCE");
    EXPECT_LT(Field(row, "translation_error_cm"), 50.0);
  }
}

// Issue 27 item 8: KITTI camera poses given as --gt_poses without
// --poses_are_camera are named in a warning with the evidence (the motion
// runs along the poses' z axis); the Velodyne poses of the same frames are
// not.
TEST(MlndtSequence, WarnsAboutCameraPosesReadAsLidarPoses) {
  const std::string dir = TestDir();
  const std::string scans =
      "--scans=" + Quote(testing::BundledDataPath("kitti/pcd")) +
      " --max_scans=2 --plots=false --output_dir=";
  const ToolRun camera =
      RunSequence(scans + Quote(dir + "/camera") + " --gt_poses=" +
                  Quote(testing::BundledDataPath("kitti/poses_cam0.txt")));
  EXPECT_NE(camera.err.find("WARNING: --gt_poses=" +
                            testing::BundledDataPath("kitti/poses_cam0.txt") +
                            " looks like KITTI camera (cam0) poses"),
            std::string::npos)
      << camera.err;
  EXPECT_NE(camera.err.find("is along the poses' z axis"), std::string::npos)
      << camera.err;
  EXPECT_NE(camera.err.find("add --poses_are_camera --calib=calib.txt"),
            std::string::npos)
      << camera.err;
  const ToolRun velodyne =
      RunSequence(scans + Quote(dir + "/velodyne") + " --gt_poses=" +
                  Quote(testing::BundledDataPath("kitti/poses_velo.txt")));
  EXPECT_EQ(velodyne.exit_code, 0) << velodyne.err;
  EXPECT_EQ(velodyne.err.find("WARNING"), std::string::npos) << velodyne.err;
}

}  // namespace
}  // namespace mlndt
