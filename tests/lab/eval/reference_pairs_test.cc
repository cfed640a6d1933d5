#include "lab/eval/reference_pairs.h"

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <string>

#include "tests/testing/scratch_dir.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

std::string WriteFile(const std::string& name, const std::string& text) {
  const std::string path = testing::ScratchPath(name);
  std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
  return path;
}

::testing::AssertionResult Contains(const std::string& text,
                                    const std::string& part) {
  if (text.find(part) != std::string::npos)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "'" << text << "' does not contain '" << part << "'";
}

const char* const kIdentity = "[1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0]";

TEST(ReadReferencePairs, KittiHasTheTwentyOnePairsOfItsReadme) {
  std::map<std::string, ReferencePair> pairs;
  std::string error;
  ASSERT_TRUE(ReadReferencePairs(
      testing::BundledDataPath("kitti/reference_pairs.json"), &pairs, &error))
      << error;
  // Consensus |t| [m] from the table in the data set's README.
  const std::map<std::string, double> readme = {
      {"0_1", 0.690}, {"1_2", 0.700}, {"2_3", 0.726}, {"3_4", 0.733},
      {"4_5", 0.737}, {"5_6", 0.764}, {"6_7", 0.778}, {"0_2", 1.382},
      {"1_3", 1.422}, {"2_4", 1.456}, {"3_5", 1.489}, {"4_6", 1.517},
      {"5_7", 1.542}, {"0_3", 2.107}, {"1_4", 2.159}, {"2_5", 2.208},
      {"3_6", 2.253}, {"4_7", 2.292}, {"0_5", 3.587}, {"1_6", 3.666},
      {"2_7", 3.743}};
  ASSERT_EQ(pairs.size(), 21u);
  for (const auto& [key, norm] : readme) {
    ASSERT_EQ(pairs.count(key), 1u) << key;
    EXPECT_NEAR(
        pairs.at(key).reference_from_input.translation().norm(), norm, 0.0006)
        << key;
    EXPECT_EQ(ReferencePairKey(pairs.at(key).reference_index,
                               pairs.at(key).input_index),
              key);
  }
  const ReferencePair& first = pairs.at("0_1");
  EXPECT_EQ(first.reference_index, 0);
  EXPECT_EQ(first.input_index, 1);
  EXPECT_DOUBLE_EQ(first.spread_m, 0.0148);
  EXPECT_DOUBLE_EQ(first.spread_deg, 0.055);
  EXPECT_DOUBLE_EQ(first.reference_from_input.translation().x(), 0.689459865);
  // The prior is the official ground truth: 0.860 m (README table).
  ASSERT_TRUE(first.prior_from_input.has_value());
  EXPECT_NEAR(first.prior_from_input->translation().norm(), 0.860, 0.0006);
}

TEST(ReadReferencePairs, Koide3PairReads) {
  std::map<std::string, ReferencePair> pairs;
  std::string error;
  ASSERT_TRUE(ReadReferencePairs(
      testing::BundledDataPath("koide3/reference_pairs.json"), &pairs, &error))
      << error;
  ASSERT_EQ(pairs.size(), 1u);
  const ReferencePair& pair = pairs.at("251370668_251371071");
  EXPECT_EQ(pair.reference_index, 251370668);
  EXPECT_EQ(pair.input_index, 251371071);
  EXPECT_DOUBLE_EQ(pair.reference_from_input.translation().y(), 0.126538434);
  EXPECT_DOUBLE_EQ(pair.spread_m, 0.0332);
  ASSERT_TRUE(pair.prior_from_input.has_value());
  EXPECT_TRUE(pair.prior_from_input->isApprox(Isometry3d::Identity()));
}

TEST(ReadReferencePairs, EverySharedDataSetReads) {
  MLNDT_REQUIRE_SHARED_DATA(dir);
  const std::map<std::string, size_t> expected = {
      {"kitti00_frames_0000_0007", 21},
      {"koide3_velodyne_pair", 1},
      {"pcl_room_scans", 1},
      {"3dtk_example_scans", 2},
      {"mulran_kaist03_keyframes", 84},
      {"fastlio_avia_hku_2_pairs", 176}};
  for (const auto& [folder, count] : expected) {
    std::map<std::string, ReferencePair> pairs;
    std::string error;
    ASSERT_TRUE(ReadReferencePairs(
        dir + "/" + folder + "/reference_pairs.json", &pairs, &error))
        << error;
    EXPECT_EQ(pairs.size(), count) << folder;
  }
}

TEST(ReadReferencePairs, OptionalPriorMayBeAbsent) {
  const std::string path = WriteFile(
      "p.json",
      std::string("{\"3_5\": {\"reference_from_input\": ") + kIdentity +
          ", \"spread_m\": 0.01, \"spread_deg\": 0.1, \"methods\": []}}");
  std::map<std::string, ReferencePair> pairs;
  std::string error;
  ASSERT_TRUE(ReadReferencePairs(path, &pairs, &error)) << error;
  EXPECT_FALSE(pairs.at("3_5").prior_from_input.has_value());
  EXPECT_EQ(pairs.at("3_5").input_index, 5);
}

// The Livox folder's README: 13 consensus entries, 163 prior entries that
// carry a "source" and no spread.
TEST(ReadReferencePairs, LivoxPriorEntriesAreMarkedBySource) {
  MLNDT_REQUIRE_SHARED_DATA(dir);
  std::map<std::string, ReferencePair> pairs;
  std::string error;
  ASSERT_TRUE(ReadReferencePairs(
      dir + "/fastlio_avia_hku_2_pairs/reference_pairs.json", &pairs, &error))
      << error;
  int consensus = 0;
  for (const auto& [key, pair] : pairs) consensus += pair.source.empty();
  EXPECT_EQ(consensus, 13);
  EXPECT_EQ(pairs.at("180_181").source.rfind("prior: FAST-LIO2", 0), 0u);
  EXPECT_EQ(pairs.at("180_181").spread_m, 0.0);
  EXPECT_TRUE(pairs.at("192_193").source.empty());
  EXPECT_GT(pairs.at("192_193").spread_m, 0.0);
}

TEST(ReadReferencePairs, SpreadsMayBeMissingOnlyWithASource) {
  const std::string path =
      WriteFile("source.json",
                std::string("{\"3_5\": {\"reference_from_input\": ") +
                    kIdentity + ", \"source\": \"prior: odometry\"}}");
  std::map<std::string, ReferencePair> pairs;
  std::string error;
  ASSERT_TRUE(ReadReferencePairs(path, &pairs, &error)) << error;
  EXPECT_EQ(pairs.at("3_5").source, "prior: odometry");
}

// A simulated set's entry (lab/sim): the exact pose, spreads 0, a source,
// and the directions the scene leaves free.
TEST(ReadReferencePairs, ReadsSimulatedEntriesWithFreeDirections) {
  const std::string path = WriteFile(
      "simulated.json",
      std::string("{\"0_1\": {\"reference_from_input\": ") + kIdentity +
          ", \"prior_from_input\": " + kIdentity +
          ", \"spread_m\": 0.0, \"spread_deg\": 0.0, \"source\": \"exact: "
          "simulated\", \"free_directions\": [[0.6, 0.8, 0, 0, 0, 0]]}, "
          "\"0_2\": {\"reference_from_input\": " +
          kIdentity +
          ", \"source\": \"exact: simulated\", \"free_directions\": []}}");
  std::map<std::string, ReferencePair> pairs;
  std::string error;
  ASSERT_TRUE(ReadReferencePairs(path, &pairs, &error)) << error;
  const ReferencePair& free = pairs.at("0_1");
  EXPECT_EQ(free.source, "exact: simulated");
  EXPECT_EQ(free.spread_m, 0.0);
  ASSERT_EQ(free.free_directions.size(), 1u);
  Vector6d expected;
  expected << 0.6, 0.8, 0, 0, 0, 0;
  EXPECT_EQ(free.free_directions[0], expected);
  EXPECT_TRUE(pairs.at("0_2").free_directions.empty());
}

struct BadCase {
  const char* name;
  std::string json;
  const char* message;  // Expected in the error, after "<path>: ".
};

TEST(ReadReferencePairs, BadFilesNameTheFileAndTheKey) {
  const std::string matrix = kIdentity;
  const std::string spreads = ", \"spread_m\": 0.01, \"spread_deg\": 0.1";
  const BadCase cases[] = {
      {"truncated",
       "{\"0_1\": {\"reference_from_input\": [1, 0",
       "malformed JSON"},
      {"not_object", "[1, 2]", "expected a JSON object"},
      {"empty", "{}", "no pairs"},
      {"bad_key",
       "{\"a_1\": {\"reference_from_input\": " + matrix + spreads + "}}",
       "key \"a_1\""},
      {"negative_key",
       "{\"-1_1\": {\"reference_from_input\": " + matrix + spreads + "}}",
       "key \"-1_1\""},
      {"missing_matrix",
       "{\"0_1\": {\"spread_m\": 0.1, \"spread_deg\": 1}}",
       "\"0_1\": reference_from_input: missing"},
      {"missing_spread",
       "{\"0_1\": {\"reference_from_input\": " + matrix +
           ", \"spread_m\": 0.01}}",
       "\"0_1\": spread_deg: missing"},
      {"short_matrix",
       "{\"0_1\": {\"reference_from_input\": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, "
       "1]" +
           spreads + "}}",
       "\"0_1\": reference_from_input: expected an array of 12 numbers "
       "(row-major 3x4), found 11 elements"},
      {"string_element",
       "{\"0_1\": {\"reference_from_input\": [1, 0, 0, \"x\", 0, 1, 0, 0, 0, "
       "0, 1, 0]" +
           spreads + "}}",
       "\"0_1\": reference_from_input: element 3 is not a finite number"},
      {"not_rotation",
       "{\"0_1\": {\"reference_from_input\": [1.1, 0, 0, 0, 0, 1, 0, 0, 0, 0, "
       "1, 0]" +
           spreads + "}}",
       "\"0_1\": reference_from_input: the 3x3 part is not a rotation"},
      {"reflection",
       "{\"0_1\": {\"reference_from_input\": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, "
       "-1, 0]" +
           spreads + "}}",
       "not a rotation"},
      {"bad_prior",
       "{\"0_1\": {\"reference_from_input\": " + matrix + spreads +
           ", \"prior_from_input\": [1, 2]}}",
       "\"0_1\": prior_from_input: expected an array of 12"},
      {"negative_spread",
       "{\"0_1\": {\"reference_from_input\": " + matrix +
           ", \"spread_m\": -0.01, \"spread_deg\": 0.1}}",
       "\"0_1\": spread_m: expected a finite number >= 0"},
      {"entry_not_object", "{\"0_1\": 5}", "\"0_1\": expected an object"},
      {"source_not_string",
       "{\"0_1\": {\"reference_from_input\": " + matrix + ", \"source\": 3}}",
       "\"0_1\": source: expected a string"},
      {"free_not_array",
       "{\"0_1\": {\"reference_from_input\": " + matrix + spreads +
           ", \"free_directions\": 1}}",
       "\"0_1\": free_directions: expected an array"},
      {"free_short",
       "{\"0_1\": {\"reference_from_input\": " + matrix + spreads +
           ", \"free_directions\": [[1, 0, 0, 0, 0]]}}",
       "\"0_1\": free_directions: direction 0: expected an array of 6"},
      {"free_not_unit",
       "{\"0_1\": {\"reference_from_input\": " + matrix + spreads +
           ", \"free_directions\": [[1, 0, 0, 0, 0, 0], [0.5, 0, 0, 0, 0, "
           "0]]}}",
       "\"0_1\": free_directions: direction 1: not of unit length"},
      {"free_string",
       "{\"0_1\": {\"reference_from_input\": " + matrix + spreads +
           ", \"free_directions\": [[1, 0, \"y\", 0, 0, 0]]}}",
       "direction 0: element 2 is not a finite number"},
  };
  for (const BadCase& c : cases) {
    const std::string path = WriteFile(std::string(c.name) + ".json", c.json);
    std::map<std::string, ReferencePair> pairs;
    std::string error;
    EXPECT_FALSE(ReadReferencePairs(path, &pairs, &error)) << c.name;
    EXPECT_TRUE(Contains(error, path + ": ")) << c.name;
    EXPECT_TRUE(Contains(error, c.message)) << c.name;
    EXPECT_TRUE(pairs.empty()) << c.name;
  }
  std::map<std::string, ReferencePair> pairs;
  std::string error;
  EXPECT_FALSE(ReadReferencePairs("/nonexistent/pairs.json", &pairs, &error));
  EXPECT_TRUE(Contains(error, "/nonexistent/pairs.json"));
}

}  // namespace
}  // namespace mlndt
