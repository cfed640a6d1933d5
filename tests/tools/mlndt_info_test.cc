// Runs the built mlndt_info binary (tests/testing/test_data.h ToolPath) on
// bundled and shared scans and checks its JSON lines, stderr and exit code.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/testing/run_tool.h"
#include "tests/testing/scratch_dir.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

using testing::ToolRun;
const auto& Quote = testing::ShellQuote;
const auto& ReadFile = testing::ReadWholeFile;

void WriteFile(const std::string& path, const std::string& contents) {
  std::ofstream out(path, std::ios::binary);
  out << contents;
  ASSERT_TRUE(out.good()) << path;
}

std::string TempPath(const std::string& name) {
  return testing::ScratchPath(name);
}

// Runs mlndt_info with `args` (already quoted where needed). ctest may run
// tests in parallel, so stderr goes to a file named after the current test.
ToolRun RunInfo(const std::string& args) {
  return testing::RunTool("mlndt_info", args);
}

// The number after `"key":` at or after `from` in `json`; NaN when absent.
// *end (may be null) receives the position after the number.
double NumberAfter(const std::string& json,
                   const std::string& key,
                   size_t from = 0,
                   size_t* end = nullptr) {
  const std::string pattern = "\"" + key + "\":";
  const size_t at = json.find(pattern, from);
  if (at == std::string::npos) return std::nan("");
  const char* begin = json.c_str() + at + pattern.size();
  while (*begin == ' ') ++begin;
  char* stop = nullptr;
  const double value = std::strtod(begin, &stop);
  if (stop == begin) return std::nan("");
  if (end != nullptr) *end = static_cast<size_t>(stop - json.c_str());
  return value;
}

// The numbers of the array after `"key":` (spaces allowed); empty when
// absent.
std::vector<double> ArrayAfter(const std::string& json,
                               const std::string& key,
                               size_t from = 0) {
  const std::string pattern = "\"" + key + "\":";
  const size_t at = json.find(pattern, from);
  if (at == std::string::npos) return {};
  const size_t open = json.find_first_not_of(' ', at + pattern.size());
  if (open == std::string::npos || json[open] != '[') return {};
  const size_t close = json.find(']', open);
  std::istringstream items(json.substr(open + 1, close - open - 1));
  std::vector<double> values;
  std::string item;
  while (std::getline(items, item, ','))
    values.push_back(std::strtod(item.c_str(), nullptr));
  return values;
}

// The string after `"key":` (no escapes expected in these tests).
std::string StringAfter(const std::string& json, const std::string& key) {
  const std::string pattern = "\"" + key + "\":";
  const size_t at = json.find(pattern);
  if (at == std::string::npos) return "";
  const size_t quote = json.find_first_not_of(' ', at + pattern.size());
  if (quote == std::string::npos || json[quote] != '"') return "";
  const size_t begin = quote + 1;
  return json.substr(begin, json.find('"', begin) - begin);
}

struct Layer {
  int layer = 0;
  double cell_size_m = 0.0;
  std::vector<double> dims;
  double occupied_cells = 0.0;
  double sparse_cells = 0.0;
};

std::vector<Layer> ParseLayers(const std::string& json) {
  std::vector<Layer> layers;
  size_t at = json.find("\"layers\":[");
  if (at == std::string::npos) return layers;
  while ((at = json.find("{\"layer\":", at)) != std::string::npos) {
    Layer layer;
    layer.layer = static_cast<int>(NumberAfter(json, "layer", at));
    layer.cell_size_m = NumberAfter(json, "cell_size_m", at);
    layer.dims = ArrayAfter(json, "dims", at);
    layer.occupied_cells = NumberAfter(json, "occupied_cells", at);
    layer.sparse_cells = NumberAfter(json, "sparse_cells", at);
    layers.push_back(layer);
    ++at;
  }
  return layers;
}

// Checks one JSON line: file, format, count, no dropped points, min < max.
void ExpectCloudLine(const std::string& line,
                     const std::string& file,
                     const std::string& format,
                     double points) {
  SCOPED_TRACE(line);
  EXPECT_EQ(StringAfter(line, "file"), file);
  EXPECT_EQ(StringAfter(line, "format"), format);
  EXPECT_EQ(NumberAfter(line, "points"), points);
  EXPECT_EQ(NumberAfter(line, "dropped_non_finite"), 0.0);
  const std::vector<double> min = ArrayAfter(line, "min_m");
  const std::vector<double> max = ArrayAfter(line, "max_m");
  ASSERT_EQ(min.size(), 3u);
  ASSERT_EQ(max.size(), 3u);
  for (int axis = 0; axis < 3; ++axis)
    EXPECT_LT(min[axis], max[axis]) << "axis " << axis;
}

const char kReference[] = "koide3/251370668.pcd";
const char kInput[] = "koide3/251371071.pcd";

TEST(MlndtInfo, DescribesBundledScans) {
  const std::string reference = testing::BundledDataPath(kReference);
  const std::string input = testing::BundledDataPath(kInput);
  const ToolRun run = RunInfo(Quote(reference) + " " + Quote(input));
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.err, "");
  ASSERT_EQ(run.lines.size(), 2u);
  ExpectCloudLine(run.lines[0], reference, "PCD", 69088);
  ExpectCloudLine(run.lines[1], input, "PCD", 69792);
  EXPECT_EQ(run.lines[0].find("\"layers\""), std::string::npos);
  EXPECT_EQ(run.lines[0].front(), '{');
  EXPECT_EQ(run.lines[0].back(), '}');
}

// --layers describes the map mlndt_align registers on when the file is its
// reference: as many layers and occupied cells (the koide3 reference has
// returns at the sensor, which the range filter drops from that map).
TEST(MlndtInfo, LayersAreThoseOfTheMapMlndtAlignBuilds) {
  const std::string reference = testing::BundledDataPath(kReference);
  const ToolRun run = RunInfo("--layers " + Quote(reference));
  EXPECT_EQ(run.exit_code, 0) << run.err;
  ASSERT_EQ(run.lines.size(), 1u);
  ExpectCloudLine(run.lines[0], reference, "PCD", 69088);
  const std::vector<Layer> layers = ParseLayers(run.lines[0]);
  const std::string json = TempPath("align.json");
  const ToolRun align = testing::RunTool(
      "mlndt_align",
      Quote(reference) + " " + Quote(testing::BundledDataPath(kInput)) +
          " --output_json=" + Quote(json));
  ASSERT_EQ(align.exit_code, 0) << align.err;
  const std::string text = testing::ReadWholeFile(json);
  double occupied = 0.0;
  for (const Layer& layer : layers) occupied += layer.occupied_cells;
  EXPECT_NE(text.find("\"num_layers\": " + std::to_string(layers.size())),
            std::string::npos)
      << run.lines[0];
  EXPECT_NE(text.find("\"map_occupied_cells\": " +
                      std::to_string(static_cast<int>(occupied))),
            std::string::npos)
      << run.lines[0];
  ASSERT_GE(layers.size(), 4u) << run.lines[0];
  for (size_t i = 0; i < layers.size(); ++i) {
    SCOPED_TRACE("layer " + std::to_string(i + 1));
    EXPECT_EQ(layers[i].layer, static_cast<int>(i + 1));
    EXPECT_GT(layers[i].cell_size_m, 0.0);
    ASSERT_EQ(layers[i].dims.size(), 3u);
    const double grid_cells =
        layers[i].dims[0] * layers[i].dims[1] * layers[i].dims[2];
    EXPECT_GT(layers[i].occupied_cells, 0.0);
    EXPECT_LE(layers[i].occupied_cells + layers[i].sparse_cells, grid_cells);
    if (i > 0) {
      // q = 8: the edge halves from one layer to the next.
      EXPECT_NEAR(layers[i].cell_size_m,
                  0.5 * layers[i - 1].cell_size_m,
                  1e-9 * layers[i - 1].cell_size_m);
      EXPECT_GE(layers[i].occupied_cells, layers[i - 1].occupied_cells);
    }
  }
}

TEST(MlndtInfo, NumLayersFlagSetsTheLayerCount) {
  const ToolRun run =
      RunInfo("--layers --num_layers=2 --finest_cell_size_m=0 " +
              Quote(testing::BundledDataPath(kReference)));
  EXPECT_EQ(run.exit_code, 0) << run.err;
  ASSERT_EQ(run.lines.size(), 1u);
  EXPECT_EQ(ParseLayers(run.lines[0]).size(), 2u) << run.lines[0];
}

TEST(MlndtInfo, FinestCellSizeChoosesTheLayerCount) {
  const ToolRun run = RunInfo("--layers --finest_cell_size_m=1 " +
                              Quote(testing::BundledDataPath(kReference)));
  EXPECT_EQ(run.exit_code, 0) << run.err;
  ASSERT_EQ(run.lines.size(), 1u);
  const std::vector<Layer> layers = ParseLayers(run.lines[0]);
  ASSERT_GE(layers.size(), 2u) << run.lines[0];
  // The fewest layers whose finest edge is <= 1 m.
  EXPECT_LE(layers.back().cell_size_m, 1.0);
  EXPECT_GT(layers[layers.size() - 2].cell_size_m, 1.0);
}

// Issue 27 item 6: a missing file is bad input, found before any work
// (exit 2, nothing described); it used to exit 1 after describing the rest.
TEST(MlndtInfo, MissingFileIsRefusedBeforeAnyFileIsDescribed) {
  const std::string missing = TempPath("does_not_exist.pcd");
  const std::string reference = testing::BundledDataPath(kReference);
  const ToolRun run = RunInfo(Quote(reference) + " " + Quote(missing));
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find(missing + ": no such readable file"),
            std::string::npos)
      << run.err;
  EXPECT_TRUE(run.lines.empty()) << run.out;
}

TEST(MlndtInfo, NoArgumentsPrintsUsage) {
  const ToolRun run = RunInfo("");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(run.lines.empty());
  EXPECT_NE(run.err.find("mlndt_info"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("FILE"), std::string::npos) << run.err;
}

TEST(MlndtInfo, MalformedFileFails) {
  const std::string bad = TempPath("malformed.pcd");
  WriteFile(bad,
            "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F "
            "F\nCOUNT 1 1 1\n"
            "WIDTH 100\nHEIGHT 1\nPOINTS 100\nDATA binary\nshort");
  const ToolRun run = RunInfo(Quote(bad));
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_TRUE(run.lines.empty());
  EXPECT_NE(run.err.find(bad), std::string::npos) << run.err;
}

TEST(MlndtInfo, GarbageFileFails) {
  const std::string bad = TempPath("garbage.pcd");
  WriteFile(bad, "this is not a point cloud\n");
  const ToolRun run = RunInfo(Quote(bad));
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_TRUE(run.lines.empty());
  EXPECT_NE(run.err.find(bad), std::string::npos) << run.err;
}

TEST(MlndtInfo, UnknownExtensionFails) {
  const std::string bad = TempPath("cloud.unknown");
  WriteFile(bad, "1 2 3\n");
  const ToolRun run = RunInfo(Quote(bad));
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_TRUE(run.lines.empty());
  EXPECT_NE(run.err.find(bad), std::string::npos) << run.err;
}

TEST(MlndtInfo, CountsDroppedNonFinitePoints) {
  const std::string path = TempPath("with_nan.pcd");
  WriteFile(path,
            "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
            "WIDTH 3\nHEIGHT 1\nPOINTS 3\nDATA ascii\n"
            "1 2 3\nnan nan nan\n-1 -2 -3\n");
  const ToolRun run = RunInfo(Quote(path));
  EXPECT_EQ(run.exit_code, 0) << run.err;
  ASSERT_EQ(run.lines.size(), 1u);
  EXPECT_EQ(NumberAfter(run.lines[0], "points"), 2.0) << run.lines[0];
  EXPECT_EQ(NumberAfter(run.lines[0], "dropped_non_finite"), 1.0)
      << run.lines[0];
  EXPECT_EQ(ArrayAfter(run.lines[0], "min_m"),
            (std::vector<double>{-1, -2, -3}));
  EXPECT_EQ(ArrayAfter(run.lines[0], "max_m"), (std::vector<double>{1, 2, 3}));
}

const char kEmptyPcd[] =
    "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
    "WIDTH 0\nHEIGHT 1\nPOINTS 0\nDATA ascii\n";

TEST(MlndtInfo, EmptyCloudIsDescribed) {
  const std::string path = TempPath("empty.pcd");
  WriteFile(path, kEmptyPcd);
  const ToolRun run = RunInfo(Quote(path));
  EXPECT_EQ(run.exit_code, 0) << run.err;
  ASSERT_EQ(run.lines.size(), 1u);
  EXPECT_EQ(NumberAfter(run.lines[0], "points"), 0.0) << run.lines[0];
  EXPECT_NE(run.lines[0].find("\"min_m\":null,\"max_m\":null"),
            std::string::npos)
      << run.lines[0];
}

TEST(MlndtInfo, EmptyCloudWithLayersFails) {
  const std::string path = TempPath("empty_layers.pcd");
  WriteFile(path, kEmptyPcd);
  const ToolRun run = RunInfo("--layers " + Quote(path));
  EXPECT_EQ(run.exit_code, 1);
  ASSERT_EQ(run.lines.size(), 1u);
  EXPECT_EQ(NumberAfter(run.lines[0], "points"), 0.0) << run.lines[0];
  EXPECT_EQ(run.lines[0].find("\"layers\""), std::string::npos) << run.lines[0];
  EXPECT_NE(run.err.find(path), std::string::npos) << run.err;
}

TEST(MlndtInfo, RejectsBadFlagCombinations) {
  const std::string reference = Quote(testing::BundledDataPath(kReference));
  for (const std::string flags :
       {"--num_layers=3",
        "--layers --num_layers=3 --finest_cell_size_m=1",
        "--layers --division_constant=1",
        "--layers --num_layers=0 --finest_cell_size_m=0",
        "--layers --num_layers=2"}) {
    SCOPED_TRACE(flags);
    const ToolRun run = RunInfo(flags + " " + reference);
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_TRUE(run.lines.empty());
    EXPECT_FALSE(run.err.empty());
  }
}

// Every scan of the shared data set, with the counts of its README.md files.
TEST(MlndtInfo, SharedDataScansHaveReadmeCounts) {
  MLNDT_REQUIRE_SHARED_DATA(dir);
  struct Expected {
    std::string relative;
    std::string format;
    double points;
  };
  const std::vector<Expected> expected = {
      {"kitti00_frames_0000_0007/pcd/000000.pcd", "PCD", 124668},
      {"kitti00_frames_0000_0007/pcd/000001.pcd", "PCD", 124605},
      {"kitti00_frames_0000_0007/pcd/000002.pcd", "PCD", 124478},
      {"kitti00_frames_0000_0007/pcd/000003.pcd", "PCD", 124167},
      {"kitti00_frames_0000_0007/pcd/000004.pcd", "PCD", 123969},
      {"kitti00_frames_0000_0007/pcd/000005.pcd", "PCD", 123924},
      {"kitti00_frames_0000_0007/pcd/000006.pcd", "PCD", 123373},
      {"kitti00_frames_0000_0007/pcd/000007.pcd", "PCD", 122765},
      {"koide3_velodyne_pair/251370668.pcd", "PCD", 69088},
      {"koide3_velodyne_pair/251371071.pcd", "PCD", 69792},
      {"koide3_velodyne_pair/target.ply", "PLY", 69088},
      {"koide3_velodyne_pair/source.ply", "PLY", 69792},
      {"pcl_room_scans/room_scan1.pcd", "PCD", 112586},
      {"pcl_room_scans/room_scan2.pcd", "PCD", 112624},
      {"3dtk_example_scans/scan000.3d", "UOS_3D", 81360},
      {"3dtk_example_scans/scan001.3d", "UOS_3D", 81360},
      {"3dtk_example_scans/scan002.3d", "UOS_3D", 81360},
  };
  std::string args;
  for (const Expected& e : expected)
    args += " " + Quote(dir + "/" + e.relative);
  const ToolRun run = RunInfo(args);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.err, "");
  ASSERT_EQ(run.lines.size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) {
    ExpectCloudLine(run.lines[i],
                    dir + "/" + expected[i].relative,
                    expected[i].format,
                    expected[i].points);
  }
}

}  // namespace
}  // namespace mlndt
