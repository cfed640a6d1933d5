// Runs the built mlndt_eval: its `chain` mode against the pairs chained
// here from the JSON; its ATE, RPE and KITTI segment errors on a
// trajectory_kitti.txt written by mlndt_sequence against values computed here
// with Eigen alone (Eigen::umeyama, the devkit's segment rule written out);
// TUM files and timestamp association; and every flag it refuses.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "lab/eval/trajectory_evaluation.h"
#include "lab/eval/trajectory_io.h"
#include "mlndt/cloud/pose_io.h"
#include "tests/testing/run_tool.h"
#include "tests/testing/scratch_dir.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

using testing::ToolRun;
const auto& Quote = testing::ShellQuote;
namespace fs = std::filesystem;
using Json = nlohmann::json;

std::string TestDir() { return testing::FreshTestDir("mlndt_eval"); }

std::string KittiPcd() { return testing::BundledDataPath("kitti/pcd"); }
std::string KittiGt() {
  return testing::BundledDataPath("kitti/poses_velo.txt");
}

std::vector<Isometry3d> ReadPoses(const std::string& path) {
  std::vector<Isometry3d> poses;
  std::string error;
  EXPECT_TRUE(ReadKittiPoses(path, &poses, &error)) << error;
  return poses;
}

// The trajectory_kitti.txt of mlndt_sequence on the bundled KITTI frames,
// written once per test process (ctest runs each test in its own process, so
// the folder is named after the test).
const std::string& SequenceTrajectory() {
  static const std::string path = [] {
    const std::string dir = testing::ScratchPath("sequence");
    fs::remove_all(dir);
    const ToolRun run = testing::RunTool(
        "mlndt_sequence",
        "--scans=" + Quote(KittiPcd()) + " --gt_poses=" + Quote(KittiGt()) +
            " --output_dir=" + Quote(dir) + " --plots=false");
    EXPECT_EQ(run.exit_code, 0) << run.err;
    return dir + "/trajectory_kitti.txt";
  }();
  return path;
}

// ---- Independent metrics (Eigen only) ---------------------------------------

// ATE RMSE after Eigen::umeyama of the positions (with or without scale).
double AteRmse(const std::vector<Isometry3d>& reference,
               const std::vector<Isometry3d>& estimate,
               bool with_scale,
               double* scale) {
  const size_t n = reference.size();
  Eigen::Matrix3Xd from(3, n), to(3, n);
  for (size_t k = 0; k < n; ++k) {
    from.col(static_cast<Eigen::Index>(k)) = estimate[k].translation();
    to.col(static_cast<Eigen::Index>(k)) = reference[k].translation();
  }
  const Eigen::Matrix4d a = Eigen::umeyama(from, to, with_scale);
  *scale = std::cbrt(a.topLeftCorner<3, 3>().determinant());
  double sum = 0.0;
  for (size_t k = 0; k < n; ++k) {
    const Eigen::Vector3d aligned =
        a.topLeftCorner<3, 3>() * from.col(static_cast<Eigen::Index>(k)) +
        a.topRightCorner<3, 1>();
    sum += (to.col(static_cast<Eigen::Index>(k)) - aligned).squaredNorm();
  }
  return std::sqrt(sum / static_cast<double>(n));
}

// RPE over (k, k + delta): RMSE of |t(Q) - t(P)| and of angle(R(Q)^T R(P))
// [deg], Q and P the reference's and the estimate's relative motions.
void RpeRmse(const std::vector<Isometry3d>& reference,
             const std::vector<Isometry3d>& estimate,
             size_t delta,
             double* translation_m,
             double* rotation_deg) {
  double t2 = 0.0, r2 = 0.0;
  size_t n = 0;
  for (size_t k = 0; k + delta < reference.size(); ++k, ++n) {
    const Isometry3d q = reference[k].inverse() * reference[k + delta];
    const Isometry3d p = estimate[k].inverse() * estimate[k + delta];
    t2 += (q.translation() - p.translation()).squaredNorm();
    const double angle =
        Eigen::AngleAxisd(q.linear().transpose() * p.linear()).angle() * 180.0 /
        M_PI;
    r2 += angle * angle;
  }
  *translation_m = std::sqrt(t2 / static_cast<double>(n));
  *rotation_deg = std::sqrt(r2 / static_cast<double>(n));
}

// The tool's JSON numbers have 10 significant digits.
constexpr double kJsonRelative = 1e-8;
#define EXPECT_JSON_NEAR(json_value, expected) \
  EXPECT_NEAR((json_value).get<double>(),      \
              (expected),                      \
              kJsonRelative* std::max(1.0, std::abs(expected)))

// The KITTI devkit's mean segment errors (evaluate_odometry.cpp) for the
// given lengths, first frames every `step`: [%] and [deg/m]; the count.
size_t KittiSegments(const std::vector<Isometry3d>& reference,
                     const std::vector<Isometry3d>& estimate,
                     const std::vector<double>& lengths,
                     size_t step,
                     double* translation_percent,
                     double* rotation_deg_per_m) {
  std::vector<double> distance = {0.0};
  for (size_t k = 1; k < reference.size(); ++k) {
    distance.push_back(
        distance.back() +
        (reference[k].translation() - reference[k - 1].translation()).norm());
  }
  double t = 0.0, r = 0.0;
  size_t n = 0;
  for (size_t first = 0; first < reference.size(); first += step) {
    for (const double length : lengths) {
      size_t last = first;
      while (last < reference.size() &&
             !(distance[last] > distance[first] + length)) {
        ++last;
      }
      if (last >= reference.size()) continue;
      const Isometry3d g = reference[first].inverse() * reference[last];
      const Isometry3d e = estimate[first].inverse() * estimate[last];
      const Isometry3d error = e.inverse() * g;
      t += error.translation().norm() / length;
      // The devkit's rotationError: acos(0.5 (trace - 1)), clamped.
      const double c = 0.5 * (error.linear().trace() - 1.0);
      r += std::acos(std::max(-1.0, std::min(1.0, c))) / length;
      ++n;
    }
  }
  *translation_percent = 100.0 * t / static_cast<double>(n);
  *rotation_deg_per_m = r / static_cast<double>(n) * 180.0 / M_PI;
  return n;
}

Json ReadJson(const std::string& path) {
  std::ifstream in(path);
  Json json;
  in >> json;
  return json;
}

// ---- chain ----------------------------------------------------------------

TEST(MlndtEval, ChainWritesTheChainedConsecutivePairs) {
  const std::string out = TestDir() + "/chained.txt";
  const std::string pairs =
      testing::BundledDataPath("kitti/reference_pairs.json");
  const ToolRun run = testing::RunTool(
      "mlndt_eval", "chain " + Quote(pairs) + " " + Quote(out));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("chained 8 poses (scans 0..7)"), std::string::npos)
      << run.out;
  // The same chain from the JSON, with Eigen.
  const Json json = ReadJson(pairs);
  std::vector<Eigen::Matrix4d> expected = {Eigen::Matrix4d::Identity()};
  for (int i = 0; i < 7; ++i) {
    const Json& m = json[std::to_string(i) + "_" + std::to_string(i + 1)]
                        ["reference_from_input"];
    Eigen::Matrix4d step = Eigen::Matrix4d::Identity();
    for (int e = 0; e < 12; ++e) step(e / 4, e % 4) = m[e].get<double>();
    expected.push_back(expected.back() * step);
  }
  // The pose reader re-orthonormalises (mlndt/common/rigid_transform.h):
  // the product of the file's 6-9 digit rotations moves by < 1e-5 (2.3e-6
  // measured on pose 7).
  const std::vector<Isometry3d> chained = ReadPoses(out);
  ASSERT_EQ(chained.size(), expected.size());
  for (size_t k = 0; k < chained.size(); ++k) {
    EXPECT_LT((chained[k].matrix() - expected[k]).cwiseAbs().maxCoeff(), 1e-5)
        << k;
  }
}

// ---- ATE / RPE / KITTI on mlndt_sequence's trajectory
// -------------------------

TEST(MlndtEval, ReproducesAteAndRpeOfASequenceTrajectory) {
  const std::string& trajectory = SequenceTrajectory();
  ASSERT_TRUE(fs::exists(trajectory));
  const std::vector<Isometry3d> reference = ReadPoses(KittiGt());
  const std::vector<Isometry3d> estimate = ReadPoses(trajectory);
  ASSERT_EQ(estimate.size(), 8u);
  for (const char* alignment : {"se3", "sim3"}) {
    for (const int delta : {1, 3}) {
      SCOPED_TRACE(std::string(alignment) + " delta " + std::to_string(delta));
      const std::string json_path = TestDir() + "/eval.json";
      const ToolRun run = testing::RunTool(
          "mlndt_eval",
          "--reference=" + Quote(KittiGt()) +
              " --estimate=" + Quote(trajectory) + " --alignment=" + alignment +
              " --delta=" + std::to_string(delta) +
              " --output_json=" + Quote(json_path));
      ASSERT_EQ(run.exit_code, 0) << run.err;
      EXPECT_NE(run.out.find("| " + trajectory + " | KITTI | 8 |"),
                std::string::npos)
          << run.out;
      const Json json = ReadJson(json_path);
      EXPECT_EQ(json["schema_version"], 2);
      EXPECT_EQ(json["tool"], "mlndt_eval");
      const Json& e = json["estimates"][0];
      // Its keys are TrajectoryEvaluationTable's (the test's Json sorts
      // them; the order is the table's, docs/json_schema.md).
      std::vector<std::string> keys, fields;
      for (const auto& item : e.items()) keys.push_back(item.key());
      for (const ResultField& f : TrajectoryEvaluationTable().fields()) {
        fields.push_back(f.name);
      }
      std::sort(fields.begin(), fields.end());
      EXPECT_EQ(keys, fields);
      EXPECT_EQ(e["pairs"].get<int>(), 8);
      EXPECT_EQ(e["association"].get<std::string>(), "index");
      double scale = 0.0;
      const double ate = AteRmse(
          reference, estimate, std::string(alignment) == "sim3", &scale);
      EXPECT_JSON_NEAR(e["ate"]["rmse_m"], ate);
      EXPECT_JSON_NEAR(e["ate"]["scale"], scale);
      EXPECT_GT(ate, 0.01);  // The data's scale bias: not a trivial zero.
      double rpe_t = 0.0, rpe_r = 0.0;
      RpeRmse(reference, estimate, static_cast<size_t>(delta), &rpe_t, &rpe_r);
      EXPECT_JSON_NEAR(e["rpe"]["translation_rmse_m"], rpe_t);
      EXPECT_JSON_NEAR(e["rpe"]["rotation_rmse_deg"], rpe_r);
      EXPECT_EQ(e["rpe"]["pairs"].get<int>(), 8 - delta);
      // 5 m of path: no KITTI segment of 100-800 m, reported as such.
      EXPECT_EQ(e["kitti"]["segments"].get<int>(), 0);
      EXPECT_TRUE(e["kitti"]["lengths"].empty());
      EXPECT_NE(run.out.find("KITTI segments: none"), std::string::npos);
    }
  }
}

// Fewer poses than delta + 1: no RPE, its numbers null (RpeSummaryTable).
TEST(MlndtEval, WritesNoRpeWhenDeltaExceedsThePairs) {
  const std::string json_path = TestDir() + "/eval.json";
  const ToolRun run =
      testing::RunTool("mlndt_eval",
                       "--reference=" + Quote(KittiGt()) +
                           " --estimate=" + Quote(SequenceTrajectory()) +
                           " --delta=10 --output_json=" + Quote(json_path));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Json rpe = ReadJson(json_path)["estimates"][0]["rpe"];
  EXPECT_EQ(rpe["pairs"].get<int>(), 0);
  EXPECT_TRUE(rpe["translation_rmse_m"].is_null());
  EXPECT_TRUE(rpe["rotation_max_deg"].is_null());
}

TEST(MlndtEval, ReproducesKittiSegmentErrorsOverShortLengths) {
  const std::string& trajectory = SequenceTrajectory();
  const std::vector<Isometry3d> reference = ReadPoses(KittiGt());
  const std::vector<Isometry3d> estimate = ReadPoses(trajectory);
  const std::string json_path = TestDir() + "/eval.json";
  const ToolRun run = testing::RunTool(
      "mlndt_eval",
      "--reference=" + Quote(KittiGt()) + " --estimate=" + Quote(trajectory) +
          " --segments_lengths_m=1,2,4,100 --segments_first_frame_step=1 "
          "--output_json=" +
          Quote(json_path));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Json json = ReadJson(json_path);
  const Json& kitti = json["estimates"][0]["kitti"];
  double t = 0.0, r = 0.0;
  const size_t n =
      KittiSegments(reference, estimate, {1, 2, 4, 100}, 1, &t, &r);
  ASSERT_GT(n, 0u);
  EXPECT_EQ(kitti["segments"].get<size_t>(), n);
  EXPECT_JSON_NEAR(kitti["translation_error_percent"], t);
  EXPECT_JSON_NEAR(kitti["rotation_error_deg_per_m"], r);
  // Reported as far as the trajectory is long: 1, 2 and 4 m, not 100 m.
  ASSERT_EQ(kitti["lengths"].size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    const double length = kitti["lengths"][i]["length_m"].get<double>();
    double tl = 0.0, rl = 0.0;
    const size_t nl = KittiSegments(reference, estimate, {length}, 1, &tl, &rl);
    EXPECT_EQ(kitti["lengths"][i]["segments"].get<size_t>(), nl);
    EXPECT_JSON_NEAR(kitti["lengths"][i]["translation_error_percent"], tl);
    EXPECT_JSON_NEAR(kitti["lengths"][i]["rotation_error_deg_per_m"], rl);
  }
  EXPECT_NE(run.out.find("KITTI segments by length: 1 m"), std::string::npos)
      << run.out;
}

// The same trajectories as TUM files (timestamps 0.1 s apart, format
// detected from the first line of a .txt): associated by timestamp, same
// ATE; a TUM estimate against a KITTI reference is paired by index.
TEST(MlndtEval, TumFilesByTimestampAndMixedFormatsByIndex) {
  const std::string dir = TestDir();
  std::string error;
  const auto to_tum =
      [&](const std::string& kitti, const std::string& tum, double offset_s) {
        Trajectory t;
        const std::vector<Isometry3d> poses = ReadPoses(kitti);
        for (size_t k = 0; k < poses.size(); ++k) {
          t.Add(100.0 + 0.1 * static_cast<double>(k) + offset_s, poses[k]);
        }
        ASSERT_TRUE(WriteTrajectory(tum, TrajectoryFormat::TUM, t, &error))
            << error;
      };
  to_tum(KittiGt(), dir + "/gt_tum.txt", 0.0);
  to_tum(SequenceTrajectory(), dir + "/estimate_tum.txt", 0.004);
  const ToolRun kitti =
      testing::RunTool("mlndt_eval",
                       "--reference=" + Quote(KittiGt()) +
                           " --estimate=" + Quote(SequenceTrajectory()) +
                           " --output_json=" + Quote(dir + "/kitti.json"));
  const ToolRun tum =
      testing::RunTool("mlndt_eval",
                       "--reference=" + Quote(dir + "/gt_tum.txt") +
                           " --estimate=" + Quote(dir + "/estimate_tum.txt") +
                           "," + Quote(SequenceTrajectory()) +
                           " --output_json=" + Quote(dir + "/tum.json"));
  ASSERT_EQ(kitti.exit_code, 0) << kitti.err;
  ASSERT_EQ(tum.exit_code, 0) << tum.err;
  const Json a = ReadJson(dir + "/kitti.json");
  const Json b = ReadJson(dir + "/tum.json");
  EXPECT_EQ(b["reference_format"].get<std::string>(), "TUM");
  ASSERT_EQ(b["estimates"].size(), 2u);
  const Json& by_time = b["estimates"][0];
  const Json& by_index = b["estimates"][1];
  EXPECT_EQ(by_time["format"].get<std::string>(), "TUM");
  EXPECT_EQ(by_time["association"].get<std::string>(), "timestamp");
  EXPECT_EQ(by_time["pairs"].get<int>(), 8);
  EXPECT_EQ(by_index["format"].get<std::string>(), "KITTI");
  EXPECT_EQ(by_index["association"].get<std::string>(), "index");
  const double ate = a["estimates"][0]["ate"]["rmse_m"].get<double>();
  EXPECT_NEAR(by_time["ate"]["rmse_m"].get<double>(), ate, 1e-9);
  EXPECT_NEAR(by_index["ate"]["rmse_m"].get<double>(), ate, 1e-9);
  // A time offset beyond --max_time_difference_s leaves no pairs.
  const ToolRun strict =
      testing::RunTool("mlndt_eval",
                       "--reference=" + Quote(dir + "/gt_tum.txt") +
                           " --estimate=" + Quote(dir + "/estimate_tum.txt") +
                           " --max_time_difference_s=0.001");
  EXPECT_EQ(strict.exit_code, 1);
  EXPECT_NE(strict.err.find("no pose pairs"), std::string::npos) << strict.err;
}

// Every misconfiguration: exit code 1 and a message naming the flag.
TEST(MlndtEval, RefusesBadFlags) {
  const std::string gt = Quote(KittiGt());
  const std::string ok = "--reference=" + gt + " --estimate=" + gt;
  const std::string pairs =
      Quote(testing::BundledDataPath("kitti/reference_pairs.json"));
  struct Case {
    std::string args;
    std::string message;
  } cases[] = {
      {"", "give --reference=FILE and --estimate=FILE"},
      {"--reference=" + gt, "give --reference=FILE and --estimate=FILE"},
      {"--estimate=" + gt, "give --reference=FILE and --estimate=FILE"},
      {"--reference=" + gt + " --estimate=" + gt + ",,x",
       "--estimate=" + KittiGt() + ",,x: an empty file name"},
      {ok + " --format=ply", "--format=ply: expected auto, kitti or tum"},
      {ok + " --reference_format=x",
       "--reference_format=x: expected auto, kitti or tum"},
      {ok + " --alignment=affine", "--alignment=affine: expected se3"},
      {ok + " --delta=0", "--delta must be >= 1"},
      {ok + " --association=nearest", "--association=nearest: expected"},
      {ok + " --max_time_difference_s=0",
       "--max_time_difference_s must be > 0"},
      {ok + " --segments_lengths_m=abc", "--segments_lengths_m=abc: expected"},
      {ok + " --segments_lengths_m=100,-5",
       "--segments_lengths_m=100,-5: expected"},
      {ok + " --segments_lengths_m=100,100", "a length is given twice"},
      {ok + " --segments_first_frame_step=0",
       "--segments_first_frame_step must be >= 1"},
      {"--reference=/nonexistent/gt.txt --estimate=" + gt,
       "--reference: /nonexistent/gt.txt"},
      {"--reference=" + gt + " --estimate=/nonexistent/e.txt",
       "/nonexistent/e.txt"},
      {"stray", "unexpected argument 'stray'"},
      {"chain " + pairs, "usage: mlndt_eval chain PAIRS.json OUT.txt"},
      {"chain " + pairs + " /tmp/x.txt --delta=2",
       "--delta does not apply to 'mlndt_eval chain'"},
      {"chain /nonexistent/pairs.json /tmp/x.txt", "/nonexistent/pairs.json"},
  };
  for (const Case& c : cases) {
    const ToolRun run = testing::RunTool("mlndt_eval", c.args);
    EXPECT_EQ(run.exit_code, 2) << c.args;
    EXPECT_NE(run.err.find(c.message), std::string::npos)
        << c.args << "\nstderr: " << run.err;
  }
}

// Issue 27 item 8: `chain` follows scan numbering with gaps (0, 2, 4, 6:
// each next scan is the nearest input of a pair from the current one; it
// failed with "no consecutive pair" before).
TEST(MlndtEval, ChainFollowsScanNumberingWithGaps) {
  const std::string dir = TestDir();
  const Json all =
      ReadJson(testing::BundledDataPath("kitti/reference_pairs.json"));
  Json gaps = Json::object();
  for (const char* key : {"0_2", "2_4", "4_6", "0_3"}) gaps[key] = all[key];
  {
    std::ofstream out(dir + "/gaps.json");
    out << gaps.dump(1);
  }
  const std::string out = dir + "/chained.txt";
  const ToolRun run = testing::RunTool(
      "mlndt_eval", "chain " + Quote(dir + "/gaps.json") + " " + Quote(out));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("chained 4 poses (scans 0..6: 0, 2, 4, 6)"),
            std::string::npos)
      << run.out;
  const std::vector<Isometry3d> chained = ReadPoses(out);
  ASSERT_EQ(chained.size(), 4u);
  Eigen::Matrix4d expected = Eigen::Matrix4d::Identity();
  for (size_t k = 1; k < chained.size(); ++k) {
    const Json& m = gaps[std::to_string(2 * (k - 1)) + "_" +
                         std::to_string(2 * k)]["reference_from_input"];
    Eigen::Matrix4d step = Eigen::Matrix4d::Identity();
    for (int e = 0; e < 12; ++e) step(e / 4, e % 4) = m[e].get<double>();
    expected = expected * step;
    EXPECT_LT((chained[k].matrix() - expected).cwiseAbs().maxCoeff(), 1e-5)
        << k;
  }
}

// Issue 27 item 8: trajectories of different lengths paired by index are
// refused (exit 2, no output), not evaluated on their common prefix in
// silence; --association=index asks for the prefix explicitly.
TEST(MlndtEval, DifferentLengthsAreRefusedUnlessIndexPairingIsAskedFor) {
  const std::string dir = TestDir();
  {
    std::ifstream in(KittiGt());
    std::ofstream out(dir + "/five.txt");
    std::string line;
    for (int k = 0; k < 5 && std::getline(in, line); ++k) out << line << "\n";
  }
  const std::string args = "--reference=" + Quote(KittiGt()) +
                           " --estimate=" + Quote(dir + "/five.txt") +
                           " --output_json=" + Quote(dir + "/eval.json");
  const ToolRun refused = testing::RunTool("mlndt_eval", args);
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
  EXPECT_NE(refused.err.find(dir + "/five.txt has 5 poses, --reference 8: "
                                   "poses are paired by index"),
            std::string::npos)
      << refused.err;
  EXPECT_FALSE(fs::exists(dir + "/eval.json"));
  const ToolRun prefix =
      testing::RunTool("mlndt_eval", args + " --association=index");
  ASSERT_EQ(prefix.exit_code, 0) << prefix.err;
  const Json json = ReadJson(dir + "/eval.json");
  EXPECT_EQ(json["estimates"][0]["pairs"].get<int>(), 5);
  EXPECT_EQ(json["estimates"][0]["association"].get<std::string>(), "index");
}

// Issue 41 item 4: a TUM file stamped with scan indices cannot pair by time
// with a timed one; of different lengths, the pair is refused (exit 2,
// naming which has stamps), not scored on the common prefix by index.
TEST(MlndtEval, IndexStampedTumAgainstTimedTumOfOtherLengthIsRefused) {
  const std::string dir = TestDir();
  const std::vector<Isometry3d> poses = ReadPoses(KittiGt());
  std::string error;
  // All 8 poses at 100 + 0.1 k s, and poses 2-7 stamped 0..5 as indices.
  Trajectory timed, indexed;
  for (size_t k = 0; k < poses.size(); ++k) {
    timed.Add(100.0 + 0.1 * static_cast<double>(k), poses[k]);
    if (k >= 2) indexed.Add(static_cast<double>(k - 2), poses[k]);
  }
  const std::string timed_path = dir + "/timed.txt";
  const std::string indexed_path = dir + "/indexed.txt";
  ASSERT_TRUE(
      WriteTrajectory(timed_path, TrajectoryFormat::TUM, timed, &error));
  ASSERT_TRUE(WriteTrajectory(indexed_path,
                              TrajectoryFormat::TUM,
                              indexed,
                              kTumIndexStampsComment,
                              &error));
  for (const auto& [reference, estimate] :
       {std::make_pair(timed_path, indexed_path),
        std::make_pair(indexed_path, timed_path)}) {
    const ToolRun run = testing::RunTool(
        "mlndt_eval",
        "--reference=" + Quote(reference) + " --estimate=" + Quote(estimate) +
            " --output_json=" + Quote(dir + "/eval.json"));
    EXPECT_EQ(run.exit_code, 2) << run.err;
    EXPECT_NE(run.err.find("poses are paired by index, so the lengths must "
                           "match"),
              std::string::npos)
        << run.err;
    EXPECT_NE(run.err.find(timed_path + " has time stamps, " + indexed_path +
                           " none"),
              std::string::npos)
        << run.err;
    EXPECT_FALSE(fs::exists(dir + "/eval.json"));
  }
}

}  // namespace
}  // namespace mlndt
