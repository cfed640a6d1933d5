#include "mlndt/grid/grid_io.h"

#include <glog/logging.h>
#include <gtest/gtest.h>

#include <fstream>
#include <random>

namespace mlndt {
namespace {

LayeredGrid MakeGrid() {
  std::mt19937 rng(11);
  std::normal_distribution<double> n(0.0, 5.0);
  PointCloud cloud;
  for (int i = 0; i < 20000; ++i)
    cloud.Add(Eigen::Vector3d(n(rng), n(rng), 0.3 * n(rng)));
  LayeredGrid grid;
  std::string error;
  CHECK(LayeredGrid::Build(PaperLayeredGridOptions(), cloud, &grid, &error))
      << error;
  return grid;
}

std::string ReadAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)),
                     std::istreambuf_iterator<char>());
}

void WriteAll(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

TEST(GridIo, RoundTripKeepsEveryCell) {
  const LayeredGrid grid = MakeGrid();
  const std::string path = ::testing::TempDir() + "/grid_round_trip.mlndtmap";
  std::string error;
  ASSERT_TRUE(SaveLayeredGrid(path, grid, &error)) << error;
  LayeredGrid loaded;
  ASSERT_TRUE(LoadLayeredGrid(path, &loaded, &error)) << error;
  ASSERT_EQ(loaded.num_layers(), grid.num_layers());
  for (int i = 1; i <= grid.num_layers(); ++i) {
    const NdtLayer& a = grid.layer(i);
    const NdtLayer& b = loaded.layer(i);
    EXPECT_EQ(a.dims(), b.dims());
    EXPECT_EQ(a.cell_size(), b.cell_size());
    ASSERT_EQ(a.cells().size(), b.cells().size());
    for (size_t c = 0; c < a.cells().size(); ++c) {
      EXPECT_EQ(a.cells()[c].mean, b.cells()[c].mean);
      EXPECT_TRUE(
          a.cells()[c].whitening.isApprox(b.cells()[c].whitening, 1e-9));
    }
    const Eigen::Vector3d probe(1.0, -2.0, 0.1);
    EXPECT_EQ(a.Lookup(probe) == nullptr, b.Lookup(probe) == nullptr);
  }
  // The map is far smaller than the 20000-point cloud (24 bytes a point).
  EXPECT_LT(ReadAll(path).size(), 20000u * 24u);
}

TEST(GridIo, CorruptTruncatedAndForeignFilesFailCleanly) {
  const LayeredGrid grid = MakeGrid();
  const std::string path = ::testing::TempDir() + "/grid_corrupt.mlndtmap";
  std::string error;
  ASSERT_TRUE(SaveLayeredGrid(path, grid, &error)) << error;
  const std::string good = ReadAll(path);

  LayeredGrid untouched;
  std::string flipped = good;
  flipped[good.size() / 2] ^= 0x5a;
  WriteAll(path, flipped);
  EXPECT_FALSE(LoadLayeredGrid(path, &untouched, &error));
  EXPECT_NE(error.find("checksum"), std::string::npos) << error;
  EXPECT_NE(error.find(path), std::string::npos);

  WriteAll(path, good.substr(0, good.size() / 3));
  EXPECT_FALSE(LoadLayeredGrid(path, &untouched, &error));

  WriteAll(path, "# .PCD v0.7 - Point Cloud Data file format\n");
  EXPECT_FALSE(LoadLayeredGrid(path, &untouched, &error));
  EXPECT_NE(error.find("magic"), std::string::npos) << error;

  EXPECT_FALSE(LoadLayeredGrid(path + ".missing", &untouched, &error));
  EXPECT_NE(error.find("missing"), std::string::npos) << error;
  EXPECT_TRUE(untouched.empty());
}

}  // namespace
}  // namespace mlndt
