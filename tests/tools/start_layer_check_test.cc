// --start_layer is checked against the map the library builds
// (tools/cli/start_layer_check.h), including LayeredGrid::Build's
// coverage rule (LayeredGridOptions::min_covered_fraction): on the bundled
// KITTI frame 0 thinned to every 40th point (as
// tests/registration/sparse_reference_test.cc), the 1.2 m rule alone
// (LayerCellSizes, which the check used before) gives one layer more than
// the map Register() builds. mlndt_align now refuses a start layer on that
// missing layer before it registers (exit 2, "the reference's map will
// have"), not after the registration ran.

#include "tools/cli/start_layer_check.h"

#include <gtest/gtest.h>

#include <string>

#include "mlndt/cloud/io.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/registration/registration.h"
#include "tests/testing/kitti_bundle.h"
#include "tests/testing/run_tool.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

// The layers of the map Register() builds, and of the 1.2 m rule alone.
void ExpectLayersOfTheLibrary(const PointCloud& reference,
                              int* built,
                              int* without_coverage) {
  const RegistrationOptions options;
  std::string error;
  int checked = 0;
  ASSERT_TRUE(
      tools::ReferenceMapNumLayers(options, reference, &checked, &error))
      << error;
  LayeredGrid map;
  ASSERT_TRUE(LayeredGrid::Build(options.grid, reference, &map, &error))
      << error;
  RegistrationSummary summary;
  Register(options, reference, reference, Isometry3d::Identity(), &summary);
  EXPECT_EQ(checked, map.num_layers());
  EXPECT_EQ(summary.num_layers, map.num_layers()) << summary.message;
  *built = map.num_layers();
  *without_coverage = static_cast<int>(
      LayerCellSizes(options.grid, BoundingBox(reference).sizes()).size());
}

TEST(ReferenceMapNumLayers, CountsTheLayersOfTheMapRegisterBuilds) {
  int built = 0, without_coverage = 0;
  ExpectLayersOfTheLibrary(
      testing::BundledKittiScan(0, 40), &built, &without_coverage);
  // The sparse scan: the coverage rule took a layer off.
  EXPECT_EQ(built + 1, without_coverage);
  // The full scan fills its finest cells: no layer taken off.
  ExpectLayersOfTheLibrary(
      testing::BundledKittiScan(0, 1), &built, &without_coverage);
  EXPECT_EQ(built, without_coverage);
}

TEST(ReferenceMapNumLayers, FailsWhereRegisterRefusesTheReference) {
  const RegistrationOptions options;
  int num_layers = 0;
  std::string error;
  EXPECT_FALSE(
      tools::ReferenceMapNumLayers(options, PointCloud(), &num_layers, &error));
  EXPECT_FALSE(error.empty());
}

TEST(MlndtAlignStartLayer, RefusesALayerTheSparseMapLacksBeforeRegistering) {
  const std::string dir = testing::FreshTestDir("start_layer_check");
  const PointCloud reference = testing::BundledKittiScan(0, 40);
  std::string error;
  ASSERT_TRUE(WritePointCloud(dir + "/ref.pcd", reference, &error)) << error;
  ASSERT_TRUE(WritePointCloud(
      dir + "/in.pcd", testing::BundledKittiScan(1, 40), &error))
      << error;
  const RegistrationOptions options;
  int built = 0;
  ASSERT_TRUE(tools::ReferenceMapNumLayers(options, reference, &built, &error));
  const std::string files = testing::ShellQuote(dir + "/ref.pcd") + " " +
                            testing::ShellQuote(dir + "/in.pcd");
  const testing::ToolRun refused = testing::RunTool(
      "mlndt_align", files + " --start_layer=" + std::to_string(built + 1));
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
  EXPECT_NE(refused.err.find("the reference's map will have " +
                             std::to_string(built) + " layer(s)"),
            std::string::npos)
      << refused.err;
  EXPECT_EQ(refused.out.find("reference_from_input"), std::string::npos)
      << "the registration ran";
  // The finest layer the map has is accepted.
  const testing::ToolRun accepted = testing::RunTool(
      "mlndt_align", files + " --start_layer=" + std::to_string(built));
  EXPECT_EQ(accepted.err.find("out of range"), std::string::npos)
      << accepted.err;
  EXPECT_NE(accepted.out.find("reference_from_input"), std::string::npos);
}

}  // namespace
}  // namespace mlndt
