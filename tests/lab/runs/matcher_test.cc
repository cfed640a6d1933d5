// The matcher switch: Method strings, validation of the chosen method's
// options, the map options each method registers on.

#include "lab/runs/matcher.h"

#include <gtest/gtest.h>

#include "tests/testing/synthetic_scene.h"

namespace mlndt {
namespace {

TEST(Method, StringsRoundTrip) {
  for (Method m : {Method::MLNDT, Method::NDT}) {
    Method parsed = m == Method::MLNDT ? Method::NDT : Method::MLNDT;
    EXPECT_TRUE(StringToMethod(MethodToString(m), &parsed));
    EXPECT_EQ(parsed, m);
  }
  Method parsed;
  EXPECT_TRUE(StringToMethod("ndt", &parsed));
  EXPECT_EQ(parsed, Method::NDT);
  EXPECT_TRUE(StringToMethod("mlndt", &parsed));
  EXPECT_EQ(parsed, Method::MLNDT);
  EXPECT_TRUE(StringToMethod("ML-NDT", &parsed));
  EXPECT_EQ(parsed, Method::MLNDT);
  EXPECT_TRUE(StringToMethod("ml_ndt", &parsed));
  EXPECT_EQ(parsed, Method::MLNDT);
  EXPECT_FALSE(StringToMethod("icp", &parsed));
}

TEST(MatcherOptions, ChecksOnlyTheChosenMethod) {
  MatcherOptions options;
  std::string error;
  EXPECT_TRUE(options.IsValid(&error)) << error;
  options.ndt.outlier_ratio = 2.0;  // Invalid, but NDT is not chosen.
  EXPECT_TRUE(options.IsValid(&error)) << error;
  options.method = Method::NDT;
  EXPECT_FALSE(options.IsValid(&error));
  options.ndt = NdtOptions();
  options.mlndt.num_threads = 0;
  EXPECT_TRUE(options.IsValid(&error)) << error;
  options.method = static_cast<Method>(7);
  EXPECT_FALSE(options.IsValid(&error));
}

TEST(MatcherGridOptions, MlNdtUsesItsMapOptionsAndNdtOneLayer) {
  const PointCloud reference = testing::StreetScene(5000, 0.02, 1);
  MatcherOptions options;
  options.mlndt.grid.finest_cell_size_m = 3.0;
  LayeredGridOptions grid;
  std::string error;
  ASSERT_TRUE(MatcherGridOptions(options, reference, &grid, &error));
  EXPECT_EQ(grid, options.mlndt.grid);
  options.method = Method::NDT;
  options.ndt.cell_size_m = 1.5;
  ASSERT_TRUE(MatcherGridOptions(options, reference, &grid, &error)) << error;
  EXPECT_EQ(grid.cell_size_m, 1.5);
}

TEST(RegisterWithMatcher, RunsTheChosenMethod) {
  const PointCloud reference = testing::StreetScene(20000, 0.02, 1);
  const PointCloud input = testing::StreetScene(20000, 0.02, 2);
  MatcherOptions options;
  RegistrationSummary summary;
  RegisterWithMatcher(
      options, reference, input, Isometry3d::Identity(), &summary);
  EXPECT_TRUE(summary.IsSolutionUsable()) << summary.message;
  EXPECT_GT(summary.num_layers, 1);
  options.method = Method::NDT;
  options.ndt.cell_size_m = 1.0;
  RegisterWithMatcher(
      options, reference, input, Isometry3d::Identity(), &summary);
  EXPECT_TRUE(summary.IsSolutionUsable()) << summary.message;
  EXPECT_EQ(summary.num_layers, 1);
}

}  // namespace
}  // namespace mlndt
