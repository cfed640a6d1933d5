// WriteSequencePlots on pair results along the bundled KITTI trajectory
// (data/kitti, frames 0-7; each estimate off its true motion by a known
// error): the figures named and written, the data files holding the
// series of the results (errors, the chained trajectory against the truth
// composed here from the poses file, one trace block per traced pair), and
// bad input refused with an error.

#include "lab/report/sequence_plots.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "lab/eval/trajectory_io.h"
#include "mlndt/common/pose.h"
#include "tests/testing/kitti_bundle.h"
#include "tests/testing/scratch_dir.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

namespace fs = std::filesystem;

bool GnuplotRuns() {
  return std::system("gnuplot --version >/dev/null 2>&1") == 0;
}

// Pairs (k, k + 1) of the KITTI poses; estimate = truth * (k + 1) cm and
// 0.1 (k + 1) deg of yaw; three trace records each.
std::vector<PairResult> Results(const std::vector<Isometry3d>& poses,
                                bool has_truth) {
  std::vector<PairResult> results;
  for (size_t k = 0; k + 1 < poses.size(); ++k) {
    PairResult r;
    r.reference = k;
    r.input = k + 1;
    r.has_truth = has_truth;
    r.truth = poses[k].inverse() * poses[k + 1];
    r.estimate = r.truth * PoseVectorToIsometry(PoseVectorFromDegrees(
                               0.01 * (k + 1), 0, 0, 0, 0, 0.1 * (k + 1)));
    r.error = ComputePoseError(r.truth, r.estimate);
    r.registration.sampled_points = 1000;
    for (int i = 1; i <= 3; ++i) {
      IterationRecord it;
      it.iteration = i;
      it.layer = i;
      it.score = 100.0 * (4 - i);
      it.reference_from_input_xi = IsometryToPoseVector(r.estimate);
      r.registration.trace.push_back(it);
    }
    results.push_back(r);
  }
  return results;
}

// The rows of a data file that are neither comments nor blank, split.
std::vector<std::vector<double>> Rows(const std::string& path,
                                      size_t* blocks = nullptr) {
  std::ifstream in(path);
  std::string line;
  std::vector<std::vector<double>> rows;
  bool in_block = false;
  if (blocks) *blocks = 0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') {
      in_block = false;
      continue;
    }
    if (!in_block && blocks) ++*blocks;
    in_block = true;
    std::istringstream fields(line);
    std::vector<double> row;
    for (double v; fields >> v;) row.push_back(v);
    rows.push_back(row);
  }
  return rows;
}

TEST(WriteSequencePlots, WritesEveryFigureAndTheResultsSeries) {
  if (!GnuplotRuns()) GTEST_SKIP() << "gnuplot is not installed";
  const std::vector<Isometry3d> poses = testing::BundledKittiPoses();
  ASSERT_EQ(poses.size(), 8u);
  const std::vector<PairResult> results = Results(poses, true);
  const std::string dir = testing::TestScratchDir();
  std::vector<std::string> pngs;
  std::string error;
  ASSERT_TRUE(WriteSequencePlots("gnuplot", dir, results, 1, 2, &pngs, &error))
      << error;
  EXPECT_EQ(pngs,
            (std::vector<std::string>{"errors_translation.png",
                                      "errors_rotation.png",
                                      "trajectory_xy.png",
                                      "score_vs_iteration.png"}));
  for (const std::string& png : pngs) {
    EXPECT_GT(fs::file_size(dir + "/" + png), 1000u) << png;
  }
  // errors.dat: input, then the error components in cm and degrees.
  const auto errors = Rows(dir + "/plot_data/errors.dat");
  ASSERT_EQ(errors.size(), results.size());
  for (size_t k = 0; k < results.size(); ++k) {
    ASSERT_EQ(errors[k].size(), 7u);
    EXPECT_EQ(errors[k][0], k + 1.0);
    EXPECT_NEAR(errors[k][1], (k + 1.0), 1e-6);      // t_x [cm].
    EXPECT_NEAR(errors[k][6], 0.1 * (k + 1), 1e-6);  // gamma [deg].
  }
  // trajectory.dat: the chained estimate, then the truth, which is
  // pose_0^-1 pose_k of the poses file.
  const auto trajectory = Rows(dir + "/plot_data/trajectory.dat");
  ASSERT_EQ(trajectory.size(), poses.size());
  for (size_t k = 0; k < poses.size(); ++k) {
    ASSERT_EQ(trajectory[k].size(), 4u);
    const Eigen::Vector3d t = (poses[0].inverse() * poses[k]).translation();
    EXPECT_NEAR(trajectory[k][2], t.x(), 1e-6 + 1e-8 * std::abs(t.x()));
    EXPECT_NEAR(trajectory[k][3], t.y(), 1e-6 + 1e-8 * std::abs(t.y()));
  }
  // The estimate starts at scan 0 and drifts from the truth (the errors
  // add up to 28 cm of t_x alone).
  EXPECT_EQ(trajectory[0][0], 0.0);
  EXPECT_GT(std::hypot(trajectory.back()[0] - trajectory.back()[2],
                       trajectory.back()[1] - trajectory.back()[3]),
            0.2);
  // trace.dat: one block per traced pair (the first and the last), the
  // score per sampled point.
  size_t blocks = 0;
  const auto trace = Rows(dir + "/plot_data/trace.dat", &blocks);
  EXPECT_EQ(blocks, 2u);
  ASSERT_EQ(trace.size(), 6u);
  EXPECT_DOUBLE_EQ(trace[0][2], 0.3);
  std::ifstream script(dir + "/plot_data/plots.gp");
  const std::string text((std::istreambuf_iterator<char>(script)),
                         std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("pair 0-1"), std::string::npos);
  EXPECT_NE(text.find("pair 6-7"), std::string::npos);
  EXPECT_EQ(text.find("pair 3-4"), std::string::npos);
}

TEST(WriteSequencePlots, WithoutTruthDrawsNoErrors) {
  if (!GnuplotRuns()) GTEST_SKIP() << "gnuplot is not installed";
  const std::string dir = testing::TestScratchDir();
  std::vector<std::string> pngs;
  std::string error;
  ASSERT_TRUE(WriteSequencePlots("gnuplot",
                                 dir,
                                 Results(testing::BundledKittiPoses(), false),
                                 1,
                                 0,
                                 &pngs,
                                 &error))
      << error;
  EXPECT_EQ(pngs, std::vector<std::string>{"trajectory_xy.png"});
  EXPECT_FALSE(fs::exists(dir + "/plot_data/errors.dat"));
  EXPECT_EQ(Rows(dir + "/plot_data/trajectory.dat")[0].size(), 2u);
}

TEST(WriteSequencePlots, RefusesAnUnusableFolderOrGnuplot) {
  const std::vector<PairResult> results =
      Results(testing::BundledKittiPoses(), true);
  const std::string file = testing::ScratchPath("not_a_folder");
  std::ofstream(file) << "x";
  std::vector<std::string> pngs;
  std::string error;
  EXPECT_FALSE(
      WriteSequencePlots("gnuplot", file, results, 1, 2, &pngs, &error));
  EXPECT_NE(error.find("not_a_folder"), std::string::npos) << error;
  error.clear();
  pngs.clear();
  EXPECT_FALSE(WriteSequencePlots("/nonexistent/gnuplot",
                                  testing::ScratchPath("plots"),
                                  results,
                                  1,
                                  2,
                                  &pngs,
                                  &error));
  EXPECT_FALSE(error.empty());
}

}  // namespace
}  // namespace mlndt
