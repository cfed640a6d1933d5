// The thread count changes the speed of a registration, never its result:
// Register (map build and Ceres solve) with num_threads 1, 2 and 4 on the
// bundled koide3 pair and KITTI 0 <- 1 must give the same bits (pose,
// scores, iterations, trace, covariance). With every input point sampled
// (thousands of residual blocks) the Ceres backend evaluates its blocks on
// several threads (solvers/internal/point_evaluation_cache.h), so the
// parallel path is compared, not only the one-thread fallback.

#include <glog/logging.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "mlndt/cloud/io.h"
#include "mlndt/common/thread_budget.h"
#include "mlndt/registration/registration.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

PointCloud ReadBundled(const std::string& relative) {
  PointCloud cloud;
  std::string error;
  CHECK(ReadPointCloud(
      testing::BundledDataPath(relative), &cloud, nullptr, &error))
      << error;
  return cloud;
}

RegistrationSummary RegisterWithThreads(RegistrationOptions options,
                                        const PointCloud& reference,
                                        const PointCloud& input,
                                        int threads) {
  options.num_threads = threads;
  RegistrationSummary summary;
  Register(options, reference, input, Isometry3d::Identity(), &summary);
  return summary;
}

// Exact comparisons of everything a caller reads.
void ExpectSameBits(const RegistrationSummary& a,
                    const RegistrationSummary& b) {
  EXPECT_EQ(a.termination_type, b.termination_type);
  EXPECT_EQ(a.num_iterations, b.num_iterations);
  EXPECT_EQ(a.iterations_per_layer, b.iterations_per_layer);
  EXPECT_EQ(a.sampled_points, b.sampled_points);
  EXPECT_EQ(a.initial_score, b.initial_score);
  EXPECT_EQ(a.final_score, b.final_score);
  EXPECT_TRUE(a.reference_from_input.matrix() ==
              b.reference_from_input.matrix())
      << a.reference_from_input.matrix() << "\nvs\n"
      << b.reference_from_input.matrix();
  EXPECT_TRUE(a.covariance == b.covariance);
  ASSERT_EQ(a.trace.size(), b.trace.size());
  for (size_t i = 0; i < a.trace.size(); ++i) {
    EXPECT_EQ(a.trace[i].score, b.trace[i].score) << "iteration " << i;
    EXPECT_TRUE(a.trace[i].reference_from_input_xi ==
                b.trace[i].reference_from_input_xi)
        << "iteration " << i;
  }
}

void CheckThreadCounts(const RegistrationOptions& options,
                       const PointCloud& reference,
                       const PointCloud& input,
                       size_t min_sampled_points) {
  const RegistrationSummary one =
      RegisterWithThreads(options, reference, input, 1);
  ASSERT_NE(one.termination_type, TerminationType::FAILURE) << one.message;
  EXPECT_GE(one.sampled_points, min_sampled_points);
  EXPECT_GT(one.num_iterations, 0);
  for (int threads : {2, 4}) {
    SCOPED_TRACE(std::to_string(threads) + " threads");
    ExpectSameBits(one,
                   RegisterWithThreads(options, reference, input, threads));
  }
}

// Every input point: enough blocks for at least 2 evaluation threads on the
// finest layer (koide3 gets 3 slices with 4 threads, KITTI 4).
RegistrationOptions AllPoints() {
  RegistrationOptions options;
  options.sampling.method = SamplingMethod::ALL;
  return options;
}

constexpr size_t kTwoThreadsOfBlocks = 2 * kMinResidualBlocksPerThread;

TEST(ThreadCount, Koide3DefaultsSameBitsFor1_2_4Threads) {
  CheckThreadCounts(RegistrationOptions(),
                    ReadBundled("koide3/251370668.pcd"),
                    ReadBundled("koide3/251371071.pcd"),
                    1);
}

TEST(ThreadCount, Koide3AllPointsSameBitsFor1_2_4Threads) {
  CheckThreadCounts(AllPoints(),
                    ReadBundled("koide3/251370668.pcd"),
                    ReadBundled("koide3/251371071.pcd"),
                    kTwoThreadsOfBlocks);
}

TEST(ThreadCount, KittiDefaultsSameBitsFor1_2_4Threads) {
  CheckThreadCounts(RegistrationOptions(),
                    ReadBundled("kitti/pcd/000000.pcd"),
                    ReadBundled("kitti/pcd/000001.pcd"),
                    1);
}

TEST(ThreadCount, KittiAllPointsSameBitsFor1_2_4Threads) {
  CheckThreadCounts(AllPoints(),
                    ReadBundled("kitti/pcd/000000.pcd"),
                    ReadBundled("kitti/pcd/000001.pcd"),
                    kTwoThreadsOfBlocks);
}

}  // namespace
}  // namespace mlndt
