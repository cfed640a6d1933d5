// RegisterPair: registers on the store's cached map of the reference, times
// the map only when it is built, and builds the map the chosen method needs.

#include "lab/runs/pair_registration.h"

#include <gtest/gtest.h>

#include "mlndt/common/pose.h"
#include "tests/testing/synthetic_sequence.h"

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
