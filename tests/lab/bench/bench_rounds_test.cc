#include "lab/bench/bench_rounds.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace mlndt {
namespace {

TEST(RoundOrder, RotatesFromRoundToRound) {
  EXPECT_EQ(RoundOrder(3, 0), (std::vector<size_t>{0, 1, 2}));
  EXPECT_EQ(RoundOrder(3, 1), (std::vector<size_t>{1, 2, 0}));
  EXPECT_EQ(RoundOrder(3, 4), (std::vector<size_t>{1, 2, 0}));
  EXPECT_EQ(RoundOrder(1, 7), (std::vector<size_t>{0}));
}

// A method that logs its calls and answers the truth shifted by `error_m`
// in x, taking `id` ms.
class FakeMethod : public BenchMethod {
 public:
  FakeMethod(int id, double error_m, std::vector<std::string>* log)
      : id_(id), error_m_(error_m), log_(log) {}
  BenchMethodLabels Labels() const override { return {}; }
  BenchEstimate Run(size_t pair_index, const ScanPair& pair) override {
    log_->push_back(std::to_string(id_) + "@" + std::to_string(pair_index));
    BenchEstimate e;
    e.reference_from_input = pair.reference_from_input_truth;
    e.reference_from_input.translation().x() += error_m_;
    e.usable = true;
    e.time_ms = id_;
    return e;
  }

 private:
  int id_;
  double error_m_;
  std::vector<std::string>* log_;
};

TEST(RunBenchRounds, AlternatesMethodsPairByPairAndScoresEveryRun) {
  std::vector<std::string> log;
  std::vector<std::unique_ptr<BenchMethod>> methods;
  methods.push_back(std::make_unique<FakeMethod>(0, 0.05, &log));
  methods.push_back(std::make_unique<FakeMethod>(1, 0.5, &log));
  const std::vector<ScanPair> pairs(2);
  BenchRoundsOptions options;
  options.repetitions = 2;
  std::vector<int> rounds_reported;
  options.on_round = [&](int round, double seconds) {
    rounds_reported.push_back(round);
    EXPECT_GE(seconds, 0.0);
  };
  const auto results = RunBenchRounds(options, methods, pairs);
  // Warm-up on the first pair, then round 0 in order 0,1 and round 1 in
  // order 1,0, pair by pair.
  EXPECT_EQ(log,
            (std::vector<std::string>{"0@0",
                                      "1@0",  // Warm-up.
                                      "0@0",
                                      "1@0",
                                      "0@1",
                                      "1@1",  // Round 0.
                                      "1@0",
                                      "0@0",
                                      "1@1",
                                      "0@1"}));
  EXPECT_EQ(rounds_reported, (std::vector<int>{1, 2}));
  ASSERT_EQ(results.size(), 2u);
  ASSERT_EQ(results[0].size(), 2u);
  ASSERT_EQ(results[0][1].size(), 2u);
  for (int round = 0; round < 2; ++round) {
    for (int p = 0; p < 2; ++p) {
      EXPECT_TRUE(results[0][round][p].success);   // 5 cm off.
      EXPECT_FALSE(results[1][round][p].success);  // 50 cm off.
      EXPECT_NEAR(results[1][round][p].translation_error_m, 0.5, 1e-12);
      EXPECT_EQ(results[1][round][p].time_ms, 1.0);
    }
  }
}

TEST(RunBenchRounds, NoWarmupWhenAskedNot) {
  std::vector<std::string> log;
  std::vector<std::unique_ptr<BenchMethod>> methods;
  methods.push_back(std::make_unique<FakeMethod>(0, 0.0, &log));
  BenchRoundsOptions options;
  options.repetitions = 1;
  options.warmup = false;
  RunBenchRounds(options, methods, std::vector<ScanPair>(1));
  EXPECT_EQ(log, (std::vector<std::string>{"0@0"}));
}

// A one-shot pair runs in a child process: the parent's log does not see
// the run, but its estimate comes back and is scored.
TEST(RunBenchRounds, OneShotPairsRunInAChildProcessAndReport) {
  std::vector<std::string> log;
  std::vector<std::unique_ptr<BenchMethod>> methods;
  methods.push_back(std::make_unique<FakeMethod>(3, 0.5, &log));
  std::vector<ScanPair> pairs(2);
  pairs[1].one_shot = true;
  BenchRoundsOptions options;
  options.repetitions = 2;
  const auto results = RunBenchRounds(options, methods, pairs);
  // Only the warm pair's warm-up and rounds ran in this process.
  EXPECT_EQ(log, (std::vector<std::string>{"3@0", "3@0", "3@0"}));
  for (int round = 0; round < 2; ++round) {
    const BenchRun& run = results[0][round][1];
    EXPECT_EQ(run.time_ms, 3.0);
    EXPECT_NEAR(run.translation_error_m, 0.5, 1e-12);
    EXPECT_FALSE(run.success);
  }
}

}  // namespace
}  // namespace mlndt
