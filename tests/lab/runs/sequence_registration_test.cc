// RunSequence on a synthetic sequence: pairs and truth, map reuse, the
// guess policies wired into the run, the adaptive start layer reaching the
// registration, releasing scans, input checks; ChainTrajectory.

#include "lab/runs/sequence_registration.h"

#include <gtest/gtest.h>

#include "mlndt/common/pose.h"
#include "tests/testing/synthetic_sequence.h"

namespace mlndt {
namespace {

constexpr int kScans = 4;

class SequenceTest : public ::testing::Test {
 protected:
  void SetUp() override {
    sequence_ = testing::WriteSyntheticSequence(
        ::testing::UnitTest::GetInstance()->current_test_info()->name(),
        kScans,
        15000,
        testing::SmallStepMotion());
  }

  // Runs the sequence with ground truth; fails the test on an error.
  std::vector<PairResult> Run(const SequenceOptions& options,
                              ScanStore* store) {
    std::vector<PairResult> results;
    std::string error;
    EXPECT_TRUE(RunSequence(options,
                            store,
                            &sequence_.world_from_scan,
                            nullptr,
                            nullptr,
                            &results,
                            &error))
        << error;
    return results;
  }

  testing::SyntheticSequence sequence_;
};

TEST_F(SequenceTest, RegistersEveryPairOnceOnMapsBuiltOnce) {
  ScanStore store(sequence_.paths);
  SequenceOptions options;
  std::vector<ProgressEvent> progress;
  ProgressFunction record(
      [&](const ProgressEvent& e) { progress.push_back(e); });
  std::vector<PairResult> results;
  std::string error;
  ASSERT_TRUE(RunSequence(options,
                          &store,
                          &sequence_.world_from_scan,
                          nullptr,
                          &record,
                          &results,
                          &error))
      << error;
  ASSERT_EQ(progress.size(), kScans - 1u);
  ASSERT_EQ(results.size(), kScans - 1u);
  for (size_t p = 0; p < results.size(); ++p) {
    const PairResult& r = results[p];
    EXPECT_EQ(r.reference, p);
    EXPECT_EQ(r.input, p + 1);
    ASSERT_TRUE(r.has_truth);
    EXPECT_TRUE(r.truth.isApprox(testing::SmallStepMotion(), 1e-9));
    EXPECT_TRUE(r.success);
    EXPECT_TRUE(r.strict_success) << r.error.translation_m;
    EXPECT_FALSE(r.guess_check_failed);
    EXPECT_EQ(progress[p].index, p);
    EXPECT_EQ(progress[p].done, p + 1);
    EXPECT_EQ(progress[p].total, kScans - 1u);
    EXPECT_EQ(
        progress[p].status.rfind("pair " + std::to_string(p) + "->" +
                                     std::to_string(p + 1) + " CONVERGENCE, ",
                                 0),
        0u)
        << progress[p].status;
    EXPECT_NE(progress[p].status.find(", error "), std::string::npos);
  }
  EXPECT_EQ(store.num_maps_built(), kScans - 1u);  // The last is no reference.
  EXPECT_GT(results[0].times.map_ms, 0.0);
}

TEST_F(SequenceTest, ConstantVelocityStartsFromThePreviousEstimate) {
  ScanStore store(sequence_.paths);
  SequenceOptions options;
  options.init.mode = InitMode::CONSTANT_VELOCITY;
  const std::vector<PairResult> results = Run(options, &store);
  ASSERT_EQ(results.size(), kScans - 1u);
  EXPECT_TRUE(results[0].guess.isApprox(Isometry3d::Identity()));
  for (size_t p = 1; p < results.size(); ++p) {
    EXPECT_TRUE(results[p].guess.isApprox(results[p - 1].estimate, 1e-12));
  }
}

TEST_F(SequenceTest, GtFractionGuessesAFractionOfTheTruth) {
  ScanStore store(sequence_.paths);
  SequenceOptions options;
  options.init.mode = InitMode::GT_FRACTION;
  options.init.fraction = 0.5;
  options.step = 2;
  const std::vector<PairResult> results = Run(options, &store);
  ASSERT_EQ(results.size(), kScans - 2u);
  for (const PairResult& r : results) {
    EXPECT_EQ(r.input, r.reference + 2);
    EXPECT_TRUE(r.guess.isApprox(ScaleMotion(r.truth, 0.5), 1e-12));
  }
}

TEST_F(SequenceTest, AdaptiveRuleMovesTheStartLayer) {
  ScanStore store(sequence_.paths);
  SequenceOptions options;
  options.adaptive.enabled = true;
  options.adaptive.max_translation_m = 1e-6;  // Every pair "fails".
  // Every map with the same layer count: the coverage rule would lower n
  // on some of these sparse synthetic scans and not on others.
  options.registration.mlndt.grid.min_covered_fraction = 0.0;
  const std::vector<PairResult> results = Run(options, &store);
  ASSERT_EQ(results.size(), kScans - 1u);
  const int last = results[0].registration.num_layers;
  ASSERT_GE(last, 3);
  EXPECT_EQ(results[0].running_fail_rate, 0.0);
  EXPECT_EQ(results[0].registration.start_layer, last);
  for (size_t p = 1; p < results.size(); ++p) {
    EXPECT_TRUE(results[p].guess_check_failed);
    EXPECT_EQ(results[p].running_fail_rate, 1.0);
    EXPECT_EQ(results[p].registration.start_layer, last - 2);
  }
}

TEST_F(SequenceTest, ReleasesScansItHasMovedPast) {
  ScanStore store(sequence_.paths);
  SequenceOptions options;
  options.release_used_scans = true;
  Run(options, &store);
  for (size_t i = 0; i < kScans - 1u; ++i) {
    EXPECT_FALSE(store.HasCloud(i)) << i;
    EXPECT_EQ(store.NumMaps(i), 0u) << i;
  }
  EXPECT_TRUE(store.HasCloud(kScans - 1));  // The last input.
}

TEST_F(SequenceTest, MissingPosesAndBadStepAreErrors) {
  ScanStore store(sequence_.paths);
  std::vector<PairResult> results;
  std::string error;
  SequenceOptions options;
  options.step = 0;
  EXPECT_FALSE(RunSequence(
      options, &store, nullptr, nullptr, nullptr, &results, &error));
  options.step = 1;
  options.init.mode = InitMode::GT_FRACTION;
  EXPECT_FALSE(RunSequence(
      options, &store, nullptr, nullptr, nullptr, &results, &error));
  EXPECT_NE(error.find("ground-truth"), std::string::npos) << error;
  options.init.mode = InitMode::POSES;
  const std::vector<Isometry3d> short_odometry(2);
  EXPECT_FALSE(RunSequence(
      options, &store, nullptr, &short_odometry, nullptr, &results, &error));
  const std::vector<Isometry3d> short_truth(2);
  options.init.mode = InitMode::ZERO;
  EXPECT_FALSE(RunSequence(
      options, &store, &short_truth, nullptr, nullptr, &results, &error));
  EXPECT_EQ(store.num_maps_built(), 0u);
}

TEST(ChainTrajectory, ComposesPairsStartingOnAStepMultiple) {
  const auto motion = [](double tx) {
    Isometry3d m = Isometry3d::Identity();
    m.translation().x() = tx;
    return m;
  };
  std::vector<PairResult> results(3);
  for (size_t p = 0; p < 3; ++p) {
    results[p].reference = p;
    results[p].estimate = motion(1.0 + p);
    results[p].truth = motion(10.0);
  }
  const std::vector<Isometry3d> step1 = ChainTrajectory(results, 1, false);
  ASSERT_EQ(step1.size(), 4u);
  EXPECT_TRUE(step1[0].isApprox(Isometry3d::Identity()));
  EXPECT_DOUBLE_EQ(step1[3].translation().x(), 6.0);
  const std::vector<Isometry3d> step2 = ChainTrajectory(results, 2, true);
  ASSERT_EQ(step2.size(), 3u);  // Pairs 0 and 2.
  EXPECT_DOUBLE_EQ(step2[2].translation().x(), 20.0);
}

}  // namespace
}  // namespace mlndt
