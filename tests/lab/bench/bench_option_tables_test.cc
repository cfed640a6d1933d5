// BenchOptionsTable: RunBench refuses a single value out of its table's
// range before any work, naming the field by its path.

#include "lab/bench/bench_option_tables.h"

#include <gtest/gtest.h>

#include "lab/bench/bench.h"

namespace mlndt {
namespace {

TEST(BenchOptionsTable, RunBenchRefusesValuesOutOfRange) {
  std::string error;
  EXPECT_TRUE(BenchOptionsTable().Check(BenchOptions(), &error)) << error;
  BenchOptions options;
  options.rounds.repetitions = 0;
  BenchResult result;
  EXPECT_FALSE(RunBench(options, &result, &error));
  EXPECT_EQ(error, "invalid option: rounds.repetitions = 0; it must be >= 1");
  options = BenchOptions();
  options.pcl.ndt_max_iterations = 0;
  EXPECT_FALSE(RunBench(options, &result, &error));
  EXPECT_EQ(error,
            "invalid option: pcl.ndt_max_iterations = 0; it must be >= 1");
  options = BenchOptions();
  options.rounds.thresholds.max_rotation_error_deg = -1.0;
  EXPECT_FALSE(RunBench(options, &result, &error));
  EXPECT_EQ(error,
            "invalid option: rounds.thresholds.max_rotation_error_deg = -1; "
            "it must be >= 0");
}

}  // namespace
}  // namespace mlndt
