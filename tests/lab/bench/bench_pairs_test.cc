#include "lab/bench/bench_pairs.h"

#include <gtest/gtest.h>

#include "mlndt/common/pose.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

// A folder with a reference_pairs.json: its pairs, the consensus as truth.
TEST(LoadBenchPairs, AnyFolderWithReferencePairs) {
  BenchPairsOptions options;
  options.data_dir = testing::BundledDataPath("koide3");
  ASSERT_TRUE(IsDatasetFolder(options.data_dir));
  std::vector<ScanPair> pairs;
  std::string error;
  ASSERT_TRUE(LoadBenchPairs(options, &pairs, &error)) << error;
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0].set, "koide3");
  EXPECT_EQ(pairs[0].reference->size(), 69088u);
  EXPECT_EQ(pairs[0].input->size(), 69792u);
  // reference_pairs.json's consensus: t = (0.4932, 0.1265, -0.0258).
  EXPECT_NEAR(
      pairs[0].reference_from_input_truth.translation().x(), 0.493198896, 1e-9);
  EXPECT_NEAR(pairs[0].reference_from_input_truth.translation().z(),
              -0.0257500727,
              1e-9);
  EXPECT_TRUE(
      pairs[0].initial_reference_from_input.isApprox(Isometry3d::Identity()));
}

// Starts: the prior and offsets of the reference, each its own set.
TEST(LoadBenchPairs, PriorAndOffsetStartsAreTheirOwnSets) {
  BenchPairsOptions options;
  options.data_dir = testing::BundledDataPath("kitti");
  options.starts = {"prior", "offsets"};
  options.offsets = "x:1";
  options.max_pairs = 2;
  std::vector<ScanPair> pairs;
  std::string error;
  ASSERT_TRUE(LoadBenchPairs(options, &pairs, &error)) << error;
  const std::vector<std::string> sets = BenchSets(pairs);
  ASSERT_EQ(sets.size(), 2u);
  EXPECT_EQ(sets[0], "kitti/prior");
  EXPECT_EQ(sets[1], "kitti/offsets");
  for (const ScanPair& pair : pairs) {
    if (pair.set != "kitti/offsets") continue;
    // The reference pushed 1 m along x.
    EXPECT_NEAR(TranslationErrorM(pair.reference_from_input_truth,
                                  pair.initial_reference_from_input),
                1.0,
                1e-6)
        << pair.label;
  }
}

// The repository's data/: koide3 and the kitti gaps asked for.
TEST(LoadBenchPairs, BundledSetsWithKittiGaps) {
  BenchPairsOptions options;
  options.data_dir = testing::BundledDataPath("");
  options.sets = {"kitti"};
  options.kitti_gaps = {2};
  std::vector<ScanPair> pairs;
  std::string error;
  ASSERT_TRUE(LoadBenchPairs(options, &pairs, &error)) << error;
  ASSERT_FALSE(pairs.empty());
  for (const ScanPair& pair : pairs) {
    EXPECT_EQ(pair.set, "kitti");
    EXPECT_EQ(pair.label.substr(6, 2), "<-") << pair.label;
    const int reference = std::stoi(pair.label.substr(0, 6));
    const int input = std::stoi(pair.label.substr(8, 6));
    EXPECT_EQ(input - reference, 2) << pair.label;
  }
}

TEST(LoadBenchPairs, RefusesBadOptionsNamingTheFlag) {
  struct Case {
    const char* prefix;
    BenchPairsOptions options;
  };
  BenchPairsOptions bundled;
  bundled.data_dir = testing::BundledDataPath("");
  std::vector<Case> cases;
  cases.push_back({"--pairs: 'bar'", bundled});
  cases.back().options.sets = {"bar"};
  cases.push_back({"--pairs: expected", bundled});
  cases.back().options.sets = {};
  cases.push_back({"--kitti_gaps", bundled});
  cases.back().options.kitti_gaps = {0};
  cases.push_back({"--starts: 'constant_velocity'", bundled});
  cases.back().options.starts = {"constant_velocity"};
  cases.push_back({"--starts: expected", bundled});
  cases.back().options.starts = {};
  cases.push_back({"--offsets", bundled});
  cases.back().options.starts = {"offsets"};
  cases.back().options.offsets = "q:1";
  cases.push_back({"--max_pairs", bundled});
  cases.back().options.max_pairs = -1;
  for (const Case& c : cases) {
    SCOPED_TRACE(c.prefix);
    std::vector<ScanPair> pairs;
    std::string error;
    EXPECT_FALSE(LoadBenchPairs(c.options, &pairs, &error));
    EXPECT_EQ(error.rfind(c.prefix, 0), 0u) << error;
  }
  // A folder without reference_pairs.json nor bundled sets.
  BenchPairsOptions missing;
  missing.data_dir = "/nonexistent";
  std::vector<ScanPair> pairs;
  std::string error;
  EXPECT_FALSE(LoadBenchPairs(missing, &pairs, &error));
  EXPECT_NE(error.find("/nonexistent"), std::string::npos) << error;
}

}  // namespace
}  // namespace mlndt
