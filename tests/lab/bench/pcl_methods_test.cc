// PCL's NDT and GICP as mlndt_bench methods on the bundled koide3 pair (in
// the build with PCL), or their absence (without).

#include "lab/bench/pcl_methods.h"

#include <gtest/gtest.h>

#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

TEST(PclBenchOptions, RefusesBadValuesNamingTheField) {
  std::string error;
  EXPECT_TRUE(PclBenchOptions().IsValid(&error)) << error;
  PclBenchOptions options;
  options.leaf_size_m = 0.0;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_EQ(error, "invalid option: leaf_size_m = 0; it must be in (0, 1e+09]");
  options = PclBenchOptions();
  options.gicp_max_iterations = 0;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_NE(error.find("gicp_max_iterations = 0"), std::string::npos);
  options = PclBenchOptions();
  options.ndt_transformation_epsilon = -1e-9;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_NE(error.find("ndt_transformation_epsilon"), std::string::npos);
}

#ifdef MLNDT_WITH_PCL
// Both reach reference_pairs.json's consensus (spread 3.3 cm, 0.48 deg) from
// the identity, well within the bench's success thresholds.
TEST(PclMethods, NdtAndGicpRegisterTheKoide3Pair) {
  ASSERT_TRUE(PclAvailable());
  BenchPairsOptions pair_options;
  pair_options.data_dir = testing::BundledDataPath("koide3");
  std::vector<ScanPair> pairs;
  std::string error;
  ASSERT_TRUE(LoadBenchPairs(pair_options, &pairs, &error)) << error;
  std::vector<std::unique_ptr<BenchMethod>> methods;
  methods.push_back(MakePclNdtMethod({}));
  methods.push_back(MakePclGicpMethod({}));
  for (const std::unique_ptr<BenchMethod>& method : methods) {
    ASSERT_NE(method, nullptr);
    const BenchMethodLabels labels = method->Labels();
    SCOPED_TRACE(labels.method);
    EXPECT_TRUE(labels.is_pcl);
    // NDT's leaf, and GICP's as the peer harness sets it up.
    EXPECT_EQ(
        labels.sampling,
        labels.method == "pcl_ndt" ? "voxel_grid_0.1" : "voxel_grid_0.25");
    ASSERT_TRUE(method->Prepare(pairs, &error)) << error;
    const BenchEstimate e = method->Run(0, pairs[0]);
    const BenchRun r =
        ScoreEstimate(e, pairs[0].reference_from_input_truth, {0.05, 0.5});
    EXPECT_TRUE(e.usable);
    EXPECT_TRUE(r.success) << r.translation_error_m << " m, "
                           << r.rotation_error_deg << " deg";
    EXPECT_GT(e.iterations, 1);
    EXPECT_GT(e.time_ms, e.align_ms);  // Filtering is in the time.
  }
  EXPECT_EQ(MakePclGicpMethod({})->Labels().method, "pcl_gicp");
}
#else
TEST(PclMethods, AbsentWithoutPcl) {
  EXPECT_FALSE(PclAvailable());
  EXPECT_EQ(MakePclNdtMethod({}), nullptr);
  EXPECT_EQ(MakePclGicpMethod({}), nullptr);
}
#endif

}  // namespace
}  // namespace mlndt
