// One map shared by several threads: four std::threads each register a
// different KITTI scan against the same const LayeredGrid (built once from
// frame 0) and must get, bit for bit, the poses, scores and iteration counts
// of one-after-the-other runs. .ci/sanitize also runs this test under
// ThreadSanitizer (OMP_NUM_THREADS=1), which reports any data race on the
// shared map or on hidden global state.
//
// Only the facade is used: Register(options, map, input, guess, &summary)
// with RegistrationOptions() defaults and one thread per registration.

#include <glog/logging.h>
#include <gtest/gtest.h>

#include <atomic>
#include <string>
#include <thread>
#include <vector>

#include "mlndt/cloud/io.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/registration/registration.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

struct Result {
  Eigen::Matrix4d reference_from_input = Eigen::Matrix4d::Zero();
  double final_score = 0.0;
  int num_iterations = 0;
  TerminationType termination = TerminationType::FAILURE;
};

PointCloud ReadKittiFrame(int frame) {
  char name[32];
  std::snprintf(name, sizeof(name), "kitti/pcd/%06d.pcd", frame);
  PointCloud cloud;
  std::string error;
  CHECK(ReadPointCloud(testing::BundledDataPath(name), &cloud, nullptr, &error))
      << error;
  return cloud;
}

Result RegisterOnce(const LayeredGrid& map, const PointCloud& input) {
  RegistrationOptions options;
  options.num_threads = 1;
  RegistrationSummary summary;
  Register(options, map, input, Isometry3d::Identity(), &summary);
  Result result;
  result.reference_from_input = summary.reference_from_input.matrix();
  result.final_score = summary.final_score;
  result.num_iterations = summary.num_iterations;
  result.termination = summary.termination_type;
  return result;
}

TEST(Concurrency, FourThreadsShareOneMapAndMatchSequentialRunsBitForBit) {
  const PointCloud reference = ReadKittiFrame(0);
  std::vector<PointCloud> inputs;
  for (int frame = 1; frame <= 4; ++frame)
    inputs.push_back(ReadKittiFrame(frame));
  LayeredGrid map;
  std::string error;
  ASSERT_TRUE(LayeredGrid::Build(LayeredGridOptions(), reference, &map, &error))
      << error;
  const LayeredGrid& shared = map;  // Every thread reads the same const map.

  std::vector<Result> sequential;
  for (const PointCloud& input : inputs) {
    sequential.push_back(RegisterOnce(shared, input));
  }

  for (int round = 0; round < 2; ++round) {
    std::vector<Result> concurrent(inputs.size());
    std::atomic<int> ready{0};
    std::vector<std::thread> threads;
    for (size_t k = 0; k < inputs.size(); ++k) {
      threads.emplace_back([&, k] {
        ready.fetch_add(1);
        while (ready.load() < static_cast<int>(inputs.size())) {
        }  // Start together, so the registrations overlap.
        concurrent[k] = RegisterOnce(shared, inputs[k]);
      });
    }
    for (std::thread& thread : threads) thread.join();
    for (size_t k = 0; k < inputs.size(); ++k) {
      SCOPED_TRACE("round " + std::to_string(round) + ", frame " +
                   std::to_string(k + 1));
      EXPECT_NE(sequential[k].termination, TerminationType::FAILURE);
      EXPECT_EQ(concurrent[k].termination, sequential[k].termination);
      EXPECT_EQ(concurrent[k].num_iterations, sequential[k].num_iterations);
      // Bit for bit: exact double comparisons.
      EXPECT_EQ(concurrent[k].final_score, sequential[k].final_score);
      EXPECT_TRUE(concurrent[k].reference_from_input ==
                  sequential[k].reference_from_input)
          << concurrent[k].reference_from_input << "\nvs\n"
          << sequential[k].reference_from_input;
    }
  }
  // The frames differ, so the four results do too (the test is not vacuous).
  EXPECT_NE(sequential[0].final_score, sequential[1].final_score);
}

}  // namespace
}  // namespace mlndt
