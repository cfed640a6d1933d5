// RegisterPair: registers on the store's cached map of the reference, times
// the map only when it is built, and builds the map the chosen method needs.

#include "lab/runs/pair_registration.h"

#include <gtest/gtest.h>

#include "mlndt/cloud/io.h"
#include "mlndt/common/pose.h"
#include "mlndt/registration/registration.h"
#include "tests/testing/synthetic_sequence.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

TEST(MatcherNumThreads, IsTheChosenMethodsThreads) {
  MatcherOptions options;
  options.mlndt.num_threads = 3;
  options.ndt.num_threads = 2;
  EXPECT_EQ(MatcherNumThreads(options), 3);
  options.method = Method::NDT;
  EXPECT_EQ(MatcherNumThreads(options), 2);
}

TEST(RegisterPair, RecoversTheMotionOnACachedMap) {
  const testing::SyntheticSequence sequence = testing::WriteSyntheticSequence(
      "pair_registration", 2, 20000, testing::SmallStepMotion());
  ScanStore store(sequence.paths);
  const MatcherOptions options;
  RegistrationSummary summary;
  PairTimes times;
  std::string error;
  ASSERT_TRUE(RegisterPair(
      options, &store, 0, 1, Isometry3d::Identity(), &summary, &times, &error))
      << error;
  ASSERT_TRUE(summary.IsSolutionUsable()) << summary.message;
  EXPECT_LT(TranslationErrorM(testing::SmallStepMotion(),
                              summary.reference_from_input),
            0.05);
  EXPECT_GT(times.map_ms, 0.0);
  EXPECT_NEAR(times.total_ms, times.map_ms + summary.total_time_s * 1e3, 1e-9);
  EXPECT_EQ(store.num_maps_built(), 1u);
  EXPECT_EQ(store.NumMaps(1), 0u);  // The input needs no map.

  // Again: the map is reused and costs nothing.
  ASSERT_TRUE(RegisterPair(
      options, &store, 0, 1, Isometry3d::Identity(), &summary, &times, &error));
  EXPECT_EQ(times.map_ms, 0.0);
  EXPECT_EQ(store.num_maps_built(), 1u);

  // NDT registers on its own one-layer grid: a second map of scan 0.
  MatcherOptions ndt;
  ndt.method = Method::NDT;
  ASSERT_TRUE(RegisterPair(
      ndt, &store, 0, 1, Isometry3d::Identity(), &summary, &times, &error))
      << error;
  EXPECT_GT(times.map_ms, 0.0);
  EXPECT_EQ(store.NumMaps(0), 2u);
  EXPECT_EQ(summary.num_layers, 1);
}

// The lab's path (a ScanStore's map) and mlndt::Register (mlndt_align,
// mlndt.register) give one answer for one pair: koide3's scans hold points
// at the sensor that the range filter drops before the map is built.
TEST(RegisterPair, GivesRegistersAnswerBitForBit) {
  const std::vector<std::string> paths = {
      testing::BundledDataPath("koide3/251370668.pcd"),
      testing::BundledDataPath("koide3/251371071.pcd")};
  ScanStore store(paths);
  const MatcherOptions options;
  RegistrationSummary lab;
  PairTimes times;
  std::string error;
  ASSERT_TRUE(RegisterPair(
      options, &store, 0, 1, Isometry3d::Identity(), &lab, &times, &error))
      << error;
  const PointCloud* reference = store.Cloud(0, &error);
  const PointCloud* input = store.Cloud(1, &error);
  ASSERT_NE(reference, nullptr);
  ASSERT_NE(input, nullptr);
  ASSERT_LT(store.ReferenceCloud(0, options.mlndt.range_filter, &error)->size(),
            reference->size());  // The filter drops points here.
  RegistrationSummary tool;
  Register(options.mlndt, *reference, *input, Isometry3d::Identity(), &tool);
  ASSERT_EQ(lab.termination_type, tool.termination_type) << lab.message;
  EXPECT_TRUE(lab.reference_from_input.matrix() ==
              tool.reference_from_input.matrix())
      << lab.reference_from_input.matrix() << "\n"
      << tool.reference_from_input.matrix();
  EXPECT_EQ(lab.final_score, tool.final_score);
}

TEST(RegisterPair, UnreadableScanIsAnError) {
  const testing::SyntheticSequence sequence = testing::WriteSyntheticSequence(
      "pair_registration_missing", 1, 5000, testing::SmallStepMotion());
  ScanStore store({sequence.paths[0], "/nonexistent.pcd"});
  RegistrationSummary summary;
  PairTimes times;
  std::string error;
  EXPECT_FALSE(RegisterPair(MatcherOptions(),
                            &store,
                            0,
                            1,
                            Isometry3d::Identity(),
                            &summary,
                            &times,
                            &error));
  EXPECT_NE(error.find("/nonexistent.pcd"), std::string::npos) << error;
}

}  // namespace
}  // namespace mlndt
