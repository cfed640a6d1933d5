// The suite's run plan: scan files found by the digits of their names (the
// pcd/ folder first, ambiguity and absence refused), the offset syntax,
// starts composed as offset ∘ reference on a known pair, the seeded
// perturbations, the start kinds that skip pairs, the pair selection and
// the run order.

#include "lab/eval/suite_plan.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "mlndt/common/pose.h"
#include "tests/testing/eigen_near.h"
#include "tests/testing/scratch_dir.h"

namespace mlndt {
namespace {

namespace fs = std::filesystem;

TEST(ScanNumberFromFileName, TakesTheDigitsOfTheNameWithoutTheExtension) {
  int64_t n = -1;
  ASSERT_TRUE(ScanNumberFromFileName("/d/pcd/000007.pcd", &n));
  EXPECT_EQ(n, 7);
  ASSERT_TRUE(ScanNumberFromFileName("scan001.3d", &n));  // Not "0013".
  EXPECT_EQ(n, 1);
  ASSERT_TRUE(ScanNumberFromFileName("room_scan1.pcd", &n));
  EXPECT_EQ(n, 1);
  ASSERT_TRUE(ScanNumberFromFileName("251370668.pcd", &n));
  EXPECT_EQ(n, 251370668);
  ASSERT_TRUE(ScanNumberFromFileName("a1b2.ply", &n));
  EXPECT_EQ(n, 12);
  // The folder's digits do not count.
  EXPECT_FALSE(ScanNumberFromFileName("/data/kitti00/target.ply", &n));
  EXPECT_FALSE(ScanNumberFromFileName("1234567890123456789.pcd", &n));
}

TEST(FindScanFile, ThePcdFolderComesFirst) {
  DatasetScanFiles files;
  files.pcd_folder = {"/d/pcd/000000.pcd", "/d/pcd/000001.pcd"};
  files.folder = {"/d/calib.txt", "/d/poses_cam0.txt", "/d/scan002.3d"};
  std::string path, error;
  // poses_cam0.txt also has the number 0, but pcd/ has the scan.
  ASSERT_TRUE(FindScanFile(files, 0, &path, &error)) << error;
  EXPECT_EQ(path, "/d/pcd/000000.pcd");
  ASSERT_TRUE(FindScanFile(files, 1, &path, &error)) << error;
  EXPECT_EQ(path, "/d/pcd/000001.pcd");
  // Not in pcd/: the folder itself.
  ASSERT_TRUE(FindScanFile(files, 2, &path, &error)) << error;
  EXPECT_EQ(path, "/d/scan002.3d");
}

TEST(FindScanFile, RefusesAmbiguousAndMissingNumbers) {
  DatasetScanFiles files;
  files.folder = {"/d/poses_cam0.txt", "/d/000000.pcd", "/d/scan7.pcd"};
  std::string path = "unchanged", error;
  EXPECT_FALSE(FindScanFile(files, 0, &path, &error));
  EXPECT_NE(error.find("ambiguous"), std::string::npos) << error;
  EXPECT_NE(error.find("/d/poses_cam0.txt"), std::string::npos) << error;
  EXPECT_NE(error.find("/d/000000.pcd"), std::string::npos) << error;
  EXPECT_EQ(path, "unchanged");
  error.clear();
  EXPECT_FALSE(FindScanFile(files, 8, &path, &error));
  EXPECT_NE(error.find("no scan file numbered 8"), std::string::npos) << error;
  // 07 is 7.
  ASSERT_TRUE(FindScanFile(files, 7, &path, &error)) << error;
  EXPECT_EQ(path, "/d/scan7.pcd");
}

TEST(ListDatasetScanFiles, ListsTheFolderAndItsPcdFolder) {
  const std::string dir = testing::ScratchPath("list");
  fs::remove_all(dir);
  fs::create_directories(dir + "/pcd");
  std::ofstream(dir + "/pcd/000003.pcd") << "x";
  std::ofstream(dir + "/poses.txt") << "x";  // Text, but not a cloud.
  std::ofstream(dir + "/scan.txt") << "1 2 3\n";
  std::ofstream(dir + "/reference_pairs.json") << "{}";
  DatasetScanFiles files;
  std::string error;
  ASSERT_TRUE(ListDatasetScanFiles(dir, &files, &error)) << error;
  ASSERT_EQ(files.pcd_folder.size(), 1u);
  EXPECT_EQ(fs::path(files.pcd_folder[0]).filename(), "000003.pcd");
  // Neither .json nor a text file whose first line is not a point.
  ASSERT_EQ(files.folder.size(), 1u);
  EXPECT_EQ(fs::path(files.folder[0]).filename(), "scan.txt");

  EXPECT_FALSE(ListDatasetScanFiles(dir + "/missing", &files, &error));
  EXPECT_NE(error.find("not a folder"), std::string::npos) << error;
  fs::remove_all(dir);
  fs::create_directories(dir);
  EXPECT_FALSE(ListDatasetScanFiles(dir, &files, &error));
  EXPECT_NE(error.find("no point-cloud files"), std::string::npos) << error;
}

TEST(StartKind, StringsRoundTrip) {
  for (const StartKind kind : {StartKind::IDENTITY,
                               StartKind::PRIOR,
                               StartKind::OFFSETS,
                               StartKind::PERTURBED,
                               StartKind::CONSTANT_VELOCITY}) {
    StartKind back = StartKind::IDENTITY;
    ASSERT_TRUE(StringToStartKind(StartKindToString(kind), &back));
    EXPECT_EQ(back, kind);
  }
  StartKind kind;
  EXPECT_TRUE(StringToStartKind("Constant_Velocity", &kind));
  EXPECT_FALSE(StringToStartKind("zero", &kind));
}

TEST(ParseStartOffsets, ParsesTheIssuesOffsets) {
  std::vector<StartOffset> offsets;
  std::string error;
  ASSERT_TRUE(ParseStartOffsets(
      "x:0.5,2,5,10;y:0.5,2,5,10;yaw:10,30,45;xyyaw:3,3,20", &offsets, &error))
      << error;
  ASSERT_EQ(offsets.size(), 12u);
  EXPECT_EQ(offsets[0].family, "x");
  EXPECT_EQ(offsets[0].label, "x=0.5");
  EXPECT_TRUE(testing::EigenNear(offsets[0].reference_xi,
                                 PoseVectorFromDegrees(0.5, 0, 0, 0, 0, 0),
                                 1e-12));
  EXPECT_EQ(offsets[5].label, "y=2");
  EXPECT_TRUE(testing::EigenNear(
      offsets[5].reference_xi, PoseVectorFromDegrees(0, 2, 0, 0, 0, 0), 1e-12));
  EXPECT_EQ(offsets[10].label, "yaw=45");
  EXPECT_TRUE(testing::EigenNear(offsets[10].reference_xi,
                                 PoseVectorFromDegrees(0, 0, 0, 0, 0, 45),
                                 1e-12));
  // Three axes: one offset of three values.
  EXPECT_EQ(offsets[11].family, "xyyaw");
  EXPECT_EQ(offsets[11].label, "xyyaw=3,3,20");
  EXPECT_TRUE(testing::EigenNear(offsets[11].reference_xi,
                                 PoseVectorFromDegrees(3, 3, 0, 0, 0, 20),
                                 1e-12));
}

TEST(ParseStartOffsets, GroupsValuesByTheAxesAndRefusesBadItems) {
  std::vector<StartOffset> offsets;
  std::string error;
  ASSERT_TRUE(
      ParseStartOffsets("z+roll+pitch:1,2,3,-1,-2,-3; x:-5", &offsets, &error))
      << error;
  ASSERT_EQ(offsets.size(), 3u);
  EXPECT_TRUE(testing::EigenNear(offsets[1].reference_xi,
                                 PoseVectorFromDegrees(0, 0, -1, -2, -3, 0),
                                 1e-12));
  EXPECT_EQ(offsets[2].family, "x");
  EXPECT_EQ(offsets[2].label, "x=-5");
  for (const char* bad : {"",
                          "x",
                          "x:",
                          "q:1",
                          "xx:1",
                          "xyyaw:3,3",
                          "x:1;",
                          "x:1,",
                          "x:a",
                          "x:1;;y:2",
                          "yaw:nan"}) {
    EXPECT_FALSE(ParseStartOffsets(bad, &offsets, &error)) << bad;
    EXPECT_FALSE(error.empty()) << bad;
  }
}

// A pair whose reference moves 1 m along x and turns 90° about z: offset ∘
// reference and reference ∘ offset differ in translation and rotation.
std::map<std::string, ReferencePair> KnownPair() {
  ReferencePair pair;
  pair.reference_index = 4;
  pair.input_index = 5;
  pair.reference_from_input =
      PoseVectorToIsometry(PoseVectorFromDegrees(1, 0, 0, 0, 0, 90));
  return {{"4_5", pair}};
}

TEST(PlanDatasetRuns, OffsetsAreAppliedInTheReferenceFrame) {
  SuitePlanOptions options;
  options.starts = {StartKind::OFFSETS};
  std::string error;
  ASSERT_TRUE(ParseStartOffsets("x:2;yaw:90", &options.offsets, &error));
  SuiteSkips skips;
  const std::vector<SuiteRun> runs =
      PlanDatasetRuns(options, 3, "set", KnownPair(), &skips);
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[0].dataset, 3u);
  EXPECT_EQ(runs[0].start, "x=2");
  EXPECT_EQ(runs[0].offset_index, 0);
  // offset ∘ reference: 2 m along the reference frame's x, so (3, 0, 0);
  // reference ∘ offset would give (1, 2, 0).
  EXPECT_TRUE(
      testing::EigenNear(runs[0].initial_reference_from_input.translation(),
                         Vector3d(3, 0, 0),
                         1e-12));
  EXPECT_TRUE(testing::EigenNear(
      IsometryToPoseVector(runs[0].initial_reference_from_input),
      PoseVectorFromDegrees(3, 0, 0, 0, 0, 90),
      1e-12));
  // 90° about the reference frame's z turns the translation too: (0, 1, 0)
  // and 180° in all (reference ∘ offset would keep (1, 0, 0)).
  EXPECT_EQ(runs[1].start, "yaw=90");
  EXPECT_TRUE(
      testing::EigenNear(runs[1].initial_reference_from_input.translation(),
                         Vector3d(0, 1, 0),
                         1e-12));
  EXPECT_NEAR(RotationErrorRad(runs[1].initial_reference_from_input,
                               Isometry3d::Identity()),
              M_PI,
              1e-12);
  for (const SuiteRun& run : runs) {
    EXPECT_TRUE(run.reference_from_input.isApprox(
        KnownPair().at("4_5").reference_from_input));
    EXPECT_FALSE(run.uncertainty.given);
  }
}

TEST(RandomStartOffset, IsBoundedSeededAndSpread) {
  double largest_m = 0.0, largest_deg = 0.0;
  for (int k = 0; k < 500; ++k) {
    const std::string text = "set/0_1/" + std::to_string(k);
    const Isometry3d offset = RandomStartOffset(0.5, 5.0, 7, text);
    const double m = offset.translation().norm();
    const double deg =
        RotationErrorRad(offset, Isometry3d::Identity()) * kRadToDeg;
    EXPECT_LE(m, 0.5);
    EXPECT_LE(deg, 5.0 + 1e-9);
    largest_m = std::max(largest_m, m);
    largest_deg = std::max(largest_deg, deg);
    EXPECT_TRUE(offset.isApprox(RandomStartOffset(0.5, 5.0, 7, text)));
  }
  EXPECT_GT(largest_m, 0.45);  // The bound is reached, not just approached.
  EXPECT_GT(largest_deg, 4.5);
  EXPECT_FALSE(RandomStartOffset(0.5, 5.0, 7, "a")
                   .isApprox(RandomStartOffset(0.5, 5.0, 8, "a")));
  EXPECT_FALSE(RandomStartOffset(0.5, 5.0, 7, "a")
                   .isApprox(RandomStartOffset(0.5, 5.0, 7, "b")));
}

// Pairs 0_1, 1_2, 2_3, 0_2, 1_3 (0_2 without a prior).
std::map<std::string, ReferencePair> Chain() {
  std::map<std::string, ReferencePair> pairs;
  for (const auto& [i, j] : std::vector<std::pair<int, int>>{
           {0, 1}, {1, 2}, {2, 3}, {0, 2}, {1, 3}}) {
    ReferencePair pair;
    pair.reference_index = i;
    pair.input_index = j;
    pair.reference_from_input =
        PoseVectorToIsometry(PoseVectorFromDegrees(i + 0.1 * j, 0, 0, 0, 0, i));
    if (!(i == 0 && j == 2)) {
      pair.prior_from_input = PoseVectorToIsometry(
          PoseVectorFromDegrees(i + 0.1 * j + 0.05, 0, 0, 0, 0, 0));
    }
    pairs[ReferencePairKey(i, j)] = pair;
  }
  return pairs;
}

TEST(PlanDatasetRuns, RunsPairsInOrderWithTheStartsInOrder) {
  SuitePlanOptions options;
  options.starts = {StartKind::PRIOR,
                    StartKind::IDENTITY,
                    StartKind::CONSTANT_VELOCITY,
                    StartKind::PERTURBED};
  options.perturb_count = 2;
  options.prior_uncertainty = {true, 0.3, 2.0};
  const auto pairs = Chain();
  SuiteSkips skips;
  const std::vector<SuiteRun> runs =
      PlanDatasetRuns(options, 0, "set", pairs, &skips);
  std::vector<std::string> order;
  for (const SuiteRun& run : runs)
    order.push_back(run.pair_key + " " + run.start);
  const std::vector<std::string> expected = {"0_1 prior",
                                             "0_1 identity",
                                             "0_1 perturbed#0",
                                             "0_1 perturbed#1",
                                             "0_2 identity",
                                             "0_2 perturbed#0",
                                             "0_2 perturbed#1",
                                             "1_2 prior",
                                             "1_2 identity",
                                             "1_2 constant_velocity",
                                             "1_2 perturbed#0",
                                             "1_2 perturbed#1",
                                             "1_3 prior",
                                             "1_3 identity",
                                             "1_3 perturbed#0",
                                             "1_3 perturbed#1",
                                             "2_3 prior",
                                             "2_3 identity",
                                             "2_3 constant_velocity",
                                             "2_3 perturbed#0",
                                             "2_3 perturbed#1"};
  EXPECT_EQ(order, expected);
  // No prior on 0_2; no previous pair for 0_1, 0_2 and 1_3 (-1_1 does
  // not exist).
  EXPECT_EQ(skips[StartKind::PRIOR], 1u);
  EXPECT_EQ(skips[StartKind::CONSTANT_VELOCITY], 3u);
  EXPECT_EQ(skips.count(StartKind::IDENTITY), 0u);
  for (const SuiteRun& run : runs) {
    EXPECT_TRUE(run.reference_from_input.isApprox(
        pairs.at(run.pair_key).reference_from_input));
    if (run.kind == StartKind::PRIOR) {
      EXPECT_TRUE(run.initial_reference_from_input.isApprox(
          *pairs.at(run.pair_key).prior_from_input));
      EXPECT_TRUE(run.uncertainty.given);
      EXPECT_EQ(run.uncertainty.translation_m, 0.3);
      EXPECT_EQ(run.uncertainty.rotation_deg, 2.0);
    }
    if (run.kind == StartKind::CONSTANT_VELOCITY) {
      // 1 -> 2 starts from the reference of 0 -> 1, 2 -> 3 from 1 -> 2.
      const std::string previous = ReferencePairKey(
          2 * run.reference_index - run.input_index, run.reference_index);
      EXPECT_TRUE(run.initial_reference_from_input.isApprox(
          pairs.at(previous).reference_from_input))
          << run.pair_key;
    }
    if (run.kind == StartKind::PERTURBED) {
      EXPECT_TRUE(run.uncertainty.given);
      EXPECT_EQ(run.uncertainty.translation_m, 0.5);
      EXPECT_EQ(run.uncertainty.rotation_deg, 5.0);
      const Isometry3d offset =
          run.initial_reference_from_input * run.reference_from_input.inverse();
      EXPECT_LE(offset.translation().norm(), 0.5 + 1e-12);
      EXPECT_GT(offset.translation().norm(), 0.0);
    }
    if (run.kind == StartKind::IDENTITY) {
      EXPECT_TRUE(
          run.initial_reference_from_input.isApprox(Isometry3d::Identity()));
      EXPECT_FALSE(run.uncertainty.given);
    }
  }
  // Perturbations depend on the pair and the index, not on the order.
  EXPECT_FALSE(runs[2].initial_reference_from_input.isApprox(
      runs[3].initial_reference_from_input));
}

TEST(PlanDatasetRuns, StartsAreRigidWhenTheFileIsNot) {
  // Matrices printed with 6 digits: |R^T R - I| ~ 1e-6.
  std::map<std::string, ReferencePair> pairs = Chain();
  for (auto& [key, pair] : pairs) {
    pair.reference_from_input.linear()(0, 1) += 3e-6;
    pair.reference_from_input.linear()(2, 0) -= 2e-6;
    if (pair.prior_from_input) pair.prior_from_input->linear()(1, 2) += 4e-6;
  }
  SuitePlanOptions options;
  options.starts = {StartKind::PRIOR,
                    StartKind::OFFSETS,
                    StartKind::PERTURBED,
                    StartKind::CONSTANT_VELOCITY};
  std::string error;
  ASSERT_TRUE(ParseStartOffsets("x:2;yaw:30", &options.offsets, &error));
  SuiteSkips skips;
  const std::vector<SuiteRun> runs =
      PlanDatasetRuns(options, 0, "set", pairs, &skips);
  ASSERT_EQ(runs.size(), 4u + 10u + 5u + 2u);  // prior, offsets, ..., cv.
  for (const SuiteRun& run : runs) {
    const Matrix3d r = run.initial_reference_from_input.linear();
    EXPECT_LT((r.transpose() * r - Matrix3d::Identity()).norm(), 1e-12)
        << run.pair_key << " " << run.start;
    EXPECT_NEAR(r.determinant(), 1.0, 1e-12);
  }
  // Made rigid, not moved: the prior start is within 1e-5 of the file's.
  EXPECT_LT((runs[0].initial_reference_from_input.matrix() -
             pairs.at("0_1").prior_from_input->matrix())
                .norm(),
            1e-5);
}

TEST(PlanDatasetRuns, SelectsPairsByStepAndCap) {
  SuitePlanOptions options;
  options.steps = {2};
  SuiteSkips skips;
  std::vector<SuiteRun> runs =
      PlanDatasetRuns(options, 0, "set", Chain(), &skips);
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[0].pair_key, "0_2");
  EXPECT_EQ(runs[1].pair_key, "1_3");

  // A single pair is kept whatever its step.
  std::map<std::string, ReferencePair> single = {
      {"251370668_251371071", Chain().at("0_1")}};
  single.begin()->second.reference_index = 251370668;
  single.begin()->second.input_index = 251371071;
  runs = PlanDatasetRuns(options, 0, "set", single, &skips);
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_EQ(runs[0].pair_key, "251370668_251371071");

  // The cap takes the smallest steps first (then the smallest reference)
  // and runs them in (reference, input) order.
  options.steps.clear();
  options.max_pairs_per_set = 4;
  runs = PlanDatasetRuns(options, 0, "set", Chain(), &skips);
  std::vector<std::string> keys;
  for (const SuiteRun& run : runs) keys.push_back(run.pair_key);
  EXPECT_EQ(keys, (std::vector<std::string>{"0_1", "0_2", "1_2", "2_3"}));
}

TEST(SuitePlanOptions, RefusesWhatCannotRun) {
  std::string error;
  SuitePlanOptions options;
  EXPECT_TRUE(options.IsValid(&error)) << error;
  options.starts = {StartKind::IDENTITY, StartKind::IDENTITY};
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_NE(error.find("twice"), std::string::npos) << error;
  options.starts = {};
  EXPECT_FALSE(options.IsValid(&error));
  options.starts = {StartKind::OFFSETS};
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_NE(error.find("offsets"), std::string::npos) << error;
  options.starts = {StartKind::PERTURBED};
  options.perturb_count = 0;
  EXPECT_FALSE(options.IsValid(&error));
  options.perturb_count = 1;
  options.perturb_rotation_deg = 200;
  EXPECT_FALSE(options.IsValid(&error));
  options.perturb_rotation_deg = 5;
  options.prior_uncertainty = {true, -1.0, 1.0};
  EXPECT_FALSE(options.IsValid(&error));
  options.prior_uncertainty = {};
  options.steps = {1, 0};
  EXPECT_FALSE(options.IsValid(&error));
}

}  // namespace
}  // namespace mlndt
