#include "mlndt/grid/grid_io.h"

#include <glog/logging.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <thread>
#include <vector>

#include "mlndt/cloud/io.h"
#include "mlndt/registration/registration.h"
#include "tests/testing/scratch_dir.h"
#include "tests/testing/small_file_system.h"
#include "tests/testing/test_data.h"

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

TEST(GridIo, CellRulesRoundTripAsVersion2) {
  // The same cloud with the library's cell rules (ndt_cell.h): line cells
  // dropped, planar cells scored along their normal.
  std::mt19937 rng(11);
  std::normal_distribution<double> n(0.0, 5.0);
  PointCloud cloud;
  for (int i = 0; i < 20000; ++i)
    cloud.Add(Eigen::Vector3d(n(rng), n(rng), 0.3 * n(rng)));
  LayeredGridOptions options = PaperLayeredGridOptions();
  options.regularization.line_ratio = 0.1;
  options.regularization.plane_ratio = 0.1;
  options.regularization.in_plane_variance_scale = 7.0;
  LayeredGrid grid;
  std::string error;
  ASSERT_TRUE(LayeredGrid::Build(options, cloud, &grid, &error)) << error;
  const std::string path = testing::ScratchPath("rules.mlndtmap");
  ASSERT_TRUE(SaveLayeredGrid(path, grid, &error)) << error;
  EXPECT_EQ(ReadAll(path)[8], 2);  // Version 2, little-endian.
  LayeredGrid loaded;
  ASSERT_TRUE(LoadLayeredGrid(path, &loaded, &error)) << error;
  EXPECT_EQ(loaded.options().regularization.in_plane_variance_scale, 7.0);
  EXPECT_EQ(loaded.options().regularization.line_ratio, 0.1);
  for (int i = 1; i <= grid.num_layers(); ++i) {
    ASSERT_EQ(grid.layer(i).keys(), loaded.layer(i).keys());
    for (size_t c = 0; c < grid.layer(i).cells().size(); ++c) {
      EXPECT_TRUE(grid.layer(i).cells()[c].information.isApprox(
          loaded.layer(i).cells()[c].information, 1e-9));
    }
  }
}

TEST(GridIo, RoundTripKeepsEveryCell) {
  const LayeredGrid grid = MakeGrid();
  const std::string path = testing::ScratchPath("round_trip.mlndtmap");
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

// A real map: the registration defaults (5 layers, 2 m finest cells) on a
// bundled KITTI frame, saved and loaded with every check of the loader.
TEST(GridIo, KittiFrameMapRoundTrips) {
  PointCloud cloud;
  std::string error;
  ASSERT_TRUE(ReadPointCloud(testing::BundledDataPath("kitti/pcd/000000.pcd"),
                             &cloud,
                             nullptr,
                             &error))
      << error;
  LayeredGrid grid;
  ASSERT_TRUE(LayeredGrid::Build(LayeredGridOptions(), cloud, &grid, &error))
      << error;
  const std::string path = testing::ScratchPath("kitti.mlndtmap");
  ASSERT_TRUE(SaveLayeredGrid(path, grid, &error)) << error;
  LayeredGrid loaded;
  ASSERT_TRUE(LoadLayeredGrid(path, &loaded, &error)) << error;
  ASSERT_EQ(loaded.num_layers(), grid.num_layers());
  for (int i = 1; i <= grid.num_layers(); ++i) {
    EXPECT_EQ(loaded.layer(i).keys(), grid.layer(i).keys());
    EXPECT_EQ(loaded.layer(i).dims(), grid.layer(i).dims());
  }
  EXPECT_EQ(loaded.num_points(), grid.num_points());
}

TEST(GridIo, CorruptTruncatedAndForeignFilesFailCleanly) {
  const LayeredGrid grid = MakeGrid();
  const std::string path = testing::ScratchPath("corrupt.mlndtmap");
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

// ---- The byte layout (little-endian, field by field) -----------------------

// The test's own little-endian encoder, independent of grid_io.cc.
class LeBytes {
 public:
  LeBytes& U32(uint32_t v) { return Int(v, 4); }
  LeBytes& I32(int32_t v) { return Int(static_cast<uint32_t>(v), 4); }
  LeBytes& U64(uint64_t v) { return Int(v, 8); }
  LeBytes& I64(int64_t v) { return Int(static_cast<uint64_t>(v), 8); }
  LeBytes& F64(double v) {
    uint64_t bits;
    std::memcpy(&bits, &v, sizeof(bits));
    return Int(bits, 8);
  }
  LeBytes& Raw(const std::string& text) {
    bytes_ += text;
    return *this;
  }
  // The file: everything so far plus its FNV-1a checksum.
  std::string WithChecksum() const {
    uint64_t hash = 14695981039346656037ull;
    for (unsigned char c : bytes_) {
      hash ^= c;
      hash *= 1099511628211ull;
    }
    LeBytes file = *this;
    file.U64(hash);
    return file.bytes_;
  }

 private:
  LeBytes& Int(uint64_t v, int size) {
    for (int i = 0; i < size; ++i)
      bytes_.push_back(static_cast<char>(v >> (8 * i)));
    return *this;
  }
  std::string bytes_;
};

// Header of a map with `layers` layers over the box [0, extent]^3.
LeBytes MapHeader(int32_t layers, double extent, uint64_t points) {
  LeBytes b;
  b.Raw("MLNDTMAP").U32(1).I32(8).I32(layers).I32(5).F64(0.01).F64(1e-3);
  for (int a = 0; a < 3; ++a) b.F64(0.0);
  for (int a = 0; a < 3; ++a) b.F64(extent);
  return b.U64(points);
}

void LayerHeader(double cell_size,
                 int32_t dims,
                 uint64_t cells,
                 LeBytes* b,
                 double origin = 0.0) {
  for (int a = 0; a < 3; ++a) b->F64(origin);
  b->F64(cell_size);
  for (int a = 0; a < 3; ++a) b->I32(dims);
  b->U64(cells);
}

void Cell(int64_t key, int32_t count, const Eigen::Vector3d& mean, LeBytes* b) {
  b->I64(key).I32(count);
  for (int a = 0; a < 3; ++a) b->F64(mean(a));
  const double upper[6] = {0.5, 0.1, 0.0, 0.4, 0.0, 0.3};  // xx xy xz yy yz zz
  for (double v : upper) b->F64(v);
}

std::string Hex(const std::string& bytes) {
  static const char* kDigits = "0123456789abcdef";
  std::string out;
  for (unsigned char c : bytes) {
    out += kDigits[c >> 4];
    out += kDigits[c & 15];
  }
  return out;
}

std::string FromHex(const std::string& hex) {
  std::string out;
  for (size_t i = 0; i + 1 < hex.size(); i += 2) {
    out.push_back(static_cast<char>(std::stoi(hex.substr(i, 2), nullptr, 16)));
  }
  return out;
}

// Saving `grid` gives a file of the size of `bytes` with the same bytes up
// to the first covariance (header, first layer header, first cell's key,
// count and mean). The covariances themselves come back through the
// eigen-decomposition of the regularisation, so only to ~1e-16.
void ExpectResavedLike(const LayeredGrid& grid, const std::string& bytes) {
  const std::string path = testing::ScratchPath("resaved.mlndtmap");
  std::string error;
  ASSERT_TRUE(SaveLayeredGrid(path, grid, &error)) << error;
  const std::string again = ReadAll(path);
  ASSERT_EQ(again.size(), bytes.size());
  constexpr size_t kPrefix = 96 + 52 + 36;
  EXPECT_EQ(Hex(again.substr(0, kPrefix)), Hex(bytes.substr(0, kPrefix)));
  LayeredGrid loaded;
  ASSERT_TRUE(LoadLayeredGrid(path, &loaded, &error)) << error;
  ASSERT_EQ(loaded.num_layers(), grid.num_layers());
  for (int i = 1; i <= grid.num_layers(); ++i) {
    EXPECT_EQ(loaded.layer(i).keys(), grid.layer(i).keys());
    for (size_t c = 0; c < grid.layer(i).cells().size(); ++c) {
      const NdtCell& a = grid.layer(i).cells()[c];
      const NdtCell& b = loaded.layer(i).cells()[c];
      EXPECT_EQ(a.count, b.count);
      EXPECT_EQ(a.mean, b.mean);
      EXPECT_TRUE(a.covariance.isApprox(b.covariance, 1e-12));
    }
  }
}

TEST(GridIo, LayoutIsLittleEndianFieldByField) {
  // Two layers over a 4 m box: 2 m cells (3^3 grid) and 1 m cells (5^3).
  LeBytes b = MapHeader(2, 4.0, 40);
  LayerHeader(2.0, 3, 1, &b);
  Cell(13, 20, Eigen::Vector3d(2.1, 2.2, 2.3), &b);
  LayerHeader(1.0, 5, 2, &b);
  Cell(0, 10, Eigen::Vector3d(0.5, 0.5, 0.5), &b);
  Cell(93, 10, Eigen::Vector3d(3.5, 3.5, 3.5), &b);  // (3, 3, 3)
  const std::string bytes = b.WithChecksum();
  const std::string path = testing::ScratchPath("layout.mlndtmap");
  WriteAll(path, bytes);

  LayeredGrid grid;
  std::string error;
  ASSERT_TRUE(LoadLayeredGrid(path, &grid, &error)) << error;
  ASSERT_EQ(grid.num_layers(), 2);
  EXPECT_EQ(grid.num_points(), 40u);
  EXPECT_EQ(grid.options().division_constant, 8);
  EXPECT_EQ(grid.bounds().max(), Eigen::Vector3d(4, 4, 4));
  EXPECT_EQ(grid.layer(1).dims(), Eigen::Vector3i(3, 3, 3));
  ASSERT_EQ(grid.layer(1).cells().size(), 1u);
  EXPECT_EQ(grid.layer(1).cells()[0].count, 20);
  EXPECT_EQ(grid.layer(1).cells()[0].mean, Eigen::Vector3d(2.1, 2.2, 2.3));
  EXPECT_EQ(grid.layer(1).keys()[0], 13);
  EXPECT_EQ(grid.layer(2).keys(), (std::vector<int64_t>{0, 93}));
  EXPECT_NE(grid.layer(2).Lookup(Eigen::Vector3d(3.6, 3.4, 3.9)), nullptr);

  const Eigen::Matrix3d& covariance = grid.layer(1).cells()[0].covariance;
  EXPECT_NEAR(covariance(0, 1), 0.1, 1e-12);
  EXPECT_NEAR(covariance(1, 0), 0.1, 1e-12);
  EXPECT_NEAR(covariance(2, 2), 0.3, 1e-12);
  ExpectResavedLike(grid, bytes);
}

// A version 1 file written by SaveLayeredGrid before the field-by-field
// little-endian writer (commit bfe223f, x86-64): 2 layers, 3 + 3 cells.
const char kVersion1Map[] =
    "4d4c4e44544d4150010000000800000002000000050000007b14ae47e17a843ffca9f1d2"
    "4d62503f6923ae43866ae7bf308298bb55a1ebbf7d177eb61381f3bf1e5a9442cf0e1a40"
    "257311d387f416403a66a6aca1fde63f24000000000000006923ae43866ae7bf308298bb"
    "55a1ebbf7d177eb61381f3bf2f5a2124401a024004000000030000000100000003000000"
    "0000000000000000000000000c00000030edb499a564c0bf0039e432c3f3823fa8b6b3ce"
    "2cbd95bf2cb85bf11d59c53fdca2634bb7032f3f46bfb9590e218c3fd101a5ad97f5c63f"
    "74c6a1aa9fe494bf14a6d4ee8190a53f020000000000000008000000a4c144a9fb791640"
    "3681bc9f0df1ea3f1c6fa7161e34dc3f531e84ee0c48ca3fe37eae903efcb13f763cc528"
    "d03eb23fbda2e4690dddb83f7cddaca7033a993f18c080e48127a33f0900000000000000"
    "09000000503ce22e6be7ff3fc0aaa56acfb4134000c5ad13a51cf0bf6a43178cfc64bc3f"
    "6f193c645ad19c3f826073783ceb953f5e7b6a8414d9c03f02122df9a514713f64e0e153"
    "50e9933f6923ae43866ae7bf308298bb55a1ebbf7d177eb61381f3bf2f5a2124401af23f"
    "07000000060000000200000003000000000000002a0000000000000007000000f07b4546"
    "a9c0c1bfa0e684f76182c9bf7cf0dec746fab63f5d656d67596eb53fb3107c671d0fa9bf"
    "b4cf73d2ba6a803f3099368cb96dc43f67dd36087860633fc9bcae581e29953f36000000"
    "0000000007000000a65949c4b5eb1640a6c0dc16fdb1eb3f221df1daef6adf3f56c518ac"
    "0ddabf3f57f7ce1e5e77ad3f556d575284d69f3f2908f0cf9caebb3f55e13b997320923f"
    "d62932a0a796943f2500000000000000050000003034e454de560140f08a0674cc9c1440"
    "ca007afc2349f0bf174d1ff19132b93ffba295d59ccdabbfb78db99e28da9b3ff6996d32"
    "aaccbd3f7ae35ad42e1a903fda508cb00828973fcdf0f86e5c06f318";

TEST(GridIo, Version1FilesFromEarlierBuildsStillLoad) {
  const std::string bytes = FromHex(kVersion1Map);
  ASSERT_EQ(bytes.size(), 712u);
  const std::string path = testing::ScratchPath("v1.mlndtmap");
  WriteAll(path, bytes);
  LayeredGrid grid;
  std::string error;
  ASSERT_TRUE(LoadLayeredGrid(path, &grid, &error)) << error;
  ASSERT_EQ(grid.num_layers(), 2);
  EXPECT_EQ(grid.num_points(), 36u);
  EXPECT_EQ(grid.layer(1).cells().size(), 3u);
  EXPECT_EQ(grid.layer(2).cells().size(), 3u);
  ExpectResavedLike(grid, bytes);
}

// ---- Crafted headers: checked before anything is allocated ------------------

struct LoadOutcome {
  bool loaded = false;
  long peak_rss_growth_kb = 0;
  double seconds = 0.0;
  char error[512] = {};
};

// Loads `bytes` in a child process and reports the result, the growth of
// the child's peak resident memory and the time taken.
LoadOutcome LoadInChild(const std::string& name, const std::string& bytes) {
  const std::string path = testing::ScratchPath("crafted_") + name;
  WriteAll(path, bytes);
  int fds[2];
  CHECK_EQ(::pipe(fds), 0);
  const pid_t pid = ::fork();
  CHECK_GE(pid, 0);
  if (pid == 0) {
    ::close(fds[0]);
    LoadOutcome outcome;
    rusage usage{};
    ::getrusage(RUSAGE_SELF, &usage);
    const long before = usage.ru_maxrss;
    const auto start = std::chrono::steady_clock::now();
    LayeredGrid grid;
    std::string error;
    outcome.loaded = LoadLayeredGrid(path, &grid, &error);
    outcome.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
            .count();
    ::getrusage(RUSAGE_SELF, &usage);
    outcome.peak_rss_growth_kb = usage.ru_maxrss - before;
    std::strncpy(outcome.error, error.c_str(), sizeof(outcome.error) - 1);
    const ssize_t written = ::write(fds[1], &outcome, sizeof(outcome));
    ::_exit(written == static_cast<ssize_t>(sizeof(outcome)) ? 0 : 1);
  }
  ::close(fds[1]);
  LoadOutcome outcome;
  const ssize_t got = ::read(fds[0], &outcome, sizeof(outcome));
  ::close(fds[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  EXPECT_EQ(got, static_cast<ssize_t>(sizeof(outcome)))
      << name << ": the child died (status " << status << ")";
  return outcome;
}

TEST(GridIo, CraftedHeadersFailFastWithSmallMemory) {
  struct Case {
    std::string name;
    std::string bytes;
    std::string keyword;
  };
  std::vector<Case> cases;
  {  // ~1 KB claiming 10^8 occupied cells in a 1000^3 grid.
    LeBytes b = MapHeader(1, 1000.0, 100000000);
    LayerHeader(1.0, 1001, 100000000, &b);
    for (int c = 0; c < 10; ++c)
      Cell(c, 10, Eigen::Vector3d(0.5 + c, 0.5, 0.5), &b);
    cases.push_back({"1e8_cells", b.WithChecksum(), "cells"});
  }
  {  // 16 layers of 256^3 = 2^24 grid cells each, no occupied cells: ~1 KB
     // that asks for 16 dense cell tables of 64 MB.
    LeBytes b = MapHeader(16, 255.5, 0);
    for (int i = 0; i < 16; ++i) LayerHeader(1.0, 256, 0, &b);
    cases.push_back({"dense_tables", b.WithChecksum(), "layer 2"});
  }
  {  // 10^8 grid cells (464^3) of 1 m over a 10 m box (11^3 would do).
    LeBytes b = MapHeader(1, 10.0, 10);
    LayerHeader(1.0, 464, 0, &b);
    cases.push_back({"dims_beyond_box", b.WithChecksum(), "dims"});
  }
  {  // Six layers consistent with a 255 m box, 1.5 m to 1 m cells, each a
     // dense grid (5M to 16.8M cells): 230 MB of cell indexes.
    LeBytes b = MapHeader(6, 255.0, 0);
    const double sizes[6] = {1.5, 1.4, 1.3, 1.2, 1.1, 1.0};
    for (double k : sizes) {
      LayerHeader(k, static_cast<int32_t>(std::floor(255.0 / k)) + 1, 0, &b);
    }
    cases.push_back({"dense_budget", b.WithChecksum(), "dense cell index"});
  }
  {  // More occupied cells than grid cells.
    LeBytes b = MapHeader(1, 1.0, 100);
    LayerHeader(1.0, 2, 9, &b);
    for (int c = 0; c < 9; ++c)
      Cell(c % 8, 10, Eigen::Vector3d(0.5, 0.5, 0.5), &b);
    cases.push_back({"cells_beyond_grid", b.WithChecksum(), "cells"});
  }
  {  // 17 layers.
    LeBytes b = MapHeader(17, 1.0, 100);
    cases.push_back({"17_layers", b.WithChecksum(), "layers"});
  }
  {  // Cell counts adding up to more points than the map was built from.
    LeBytes b = MapHeader(1, 1.0, 15);
    LayerHeader(1.0, 2, 2, &b);
    Cell(0, 10, Eigen::Vector3d(0.5, 0.5, 0.5), &b);
    Cell(1, 10, Eigen::Vector3d(1.5, 0.5, 0.5), &b);
    cases.push_back({"counts_beyond_points", b.WithChecksum(), "points"});
  }
  {  // A cell whose mean lies two cells away from it.
    LeBytes b = MapHeader(1, 1.0, 100);
    LayerHeader(1.0, 2, 1, &b);
    Cell(0, 10, Eigen::Vector3d(2.5, 0.5, 0.5), &b);
    cases.push_back({"mean_outside_cell", b.WithChecksum(), "mean outside"});
  }
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    EXPECT_LT(c.bytes.size(), 2000u);
    const LoadOutcome outcome = LoadInChild(c.name, c.bytes);
    std::printf("crafted %-20s %4zu bytes: peak RSS +%ld KB, %.2f ms: %s\n",
                c.name.c_str(),
                c.bytes.size(),
                outcome.peak_rss_growth_kb,
                outcome.seconds * 1e3,
                outcome.error);
    EXPECT_FALSE(outcome.loaded);
    EXPECT_NE(std::string(outcome.error).find("crafted_" + c.name),
              std::string::npos)
        << outcome.error;
    EXPECT_NE(std::string(outcome.error).find(c.keyword), std::string::npos)
        << outcome.error;
    EXPECT_LT(outcome.peak_rss_growth_kb, 32 * 1024) << outcome.error;
    EXPECT_LT(outcome.seconds, 0.5);
  }
}

// ---- Saving: concurrent writers, special targets, modes, a full disk --------

TEST(SaveLayeredGrid, TwoThreadsSavingOneMapToOnePathBothSucceed) {
  const LayeredGrid grid = MakeGrid();
  const std::string folder = testing::ScratchPath("concurrent");
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  const std::string path = folder + "/map.mlndtmap";
  for (int round = 0; round < 50; ++round) {
    bool ok[2] = {false, false};
    std::string errors[2];
    std::atomic<int> ready{0};
    auto save = [&](int k) {
      ready.fetch_add(1);
      while (ready.load() < 2) {
      }  // Start both saves together.
      ok[k] = SaveLayeredGrid(path, grid, &errors[k]);
    };
    std::thread first(save, 0);
    std::thread second(save, 1);
    first.join();
    second.join();
    ASSERT_TRUE(ok[0]) << "round " << round << ": " << errors[0];
    ASSERT_TRUE(ok[1]) << "round " << round << ": " << errors[1];
    LayeredGrid loaded;
    std::string error;
    ASSERT_TRUE(LoadLayeredGrid(path, &loaded, &error)) << error;
    ASSERT_EQ(loaded.num_layers(), grid.num_layers());
  }
  size_t entries = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    EXPECT_EQ(entry.path().filename(), "map.mlndtmap");
    ++entries;
  }
  EXPECT_EQ(entries, 1u);  // No temporary file left behind.
}

TEST(SaveLayeredGrid, RefusesSymlinkAndFifoTargetsAndKeepsTheFileMode) {
  const LayeredGrid grid = MakeGrid();
  const std::string folder = testing::ScratchPath("special");
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  const std::string victim = folder + "/victim.txt";
  WriteAll(victim, "victim");
  const std::string link = folder + "/link.mlndtmap";
  ASSERT_EQ(::symlink(victim.c_str(), link.c_str()), 0);
  const std::string fifo = folder + "/fifo.mlndtmap";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  std::string error;
  EXPECT_FALSE(SaveLayeredGrid(link, grid, &error));
  EXPECT_NE(error.find("symbolic link"), std::string::npos) << error;
  EXPECT_TRUE(std::filesystem::is_symlink(link));
  EXPECT_EQ(ReadAll(victim), "victim");
  EXPECT_FALSE(SaveLayeredGrid(fifo, grid, &error));
  EXPECT_NE(error.find("FIFO"), std::string::npos) << error;
  EXPECT_TRUE(std::filesystem::is_fifo(fifo));

  const std::string path = folder + "/private.mlndtmap";
  WriteAll(path, "old");
  ASSERT_EQ(::chmod(path.c_str(), 0600), 0);
  ASSERT_TRUE(SaveLayeredGrid(path, grid, &error)) << error;
  struct stat status;
  ASSERT_EQ(::stat(path.c_str(), &status), 0);
  EXPECT_EQ(status.st_mode & 07777, 0600u);
}

TEST(SaveLayeredGrid, FullFileSystemKeepsThePreviousMap) {
  const LayeredGrid big = MakeGrid();
  const std::string scratch = testing::ScratchPath("big.mlndtmap");
  std::string error;
  ASSERT_TRUE(SaveLayeredGrid(scratch, big, &error)) << error;
  ASSERT_GT(ReadAll(scratch).size(), 64u * 1024u);

  testing::SmallFileSystem fs;
  MLNDT_MOUNT_SMALL_FS_OR_SKIP(fs, 64 * 1024);
  const size_t free_at_start = fs.FreeBytes();
  const std::string path = fs.path() + "/map.mlndtmap";
  WriteAll(path, FromHex(kVersion1Map));
  const std::string before = ReadAll(path);
  EXPECT_FALSE(SaveLayeredGrid(path, big, &error));
  EXPECT_NE(error.find(path), std::string::npos) << error;
  EXPECT_NE(error.find(std::strerror(ENOSPC)), std::string::npos) << error;
  EXPECT_EQ(ReadAll(path), before);
  LayeredGrid loaded;
  EXPECT_TRUE(LoadLayeredGrid(path, &loaded, &error)) << error;
  size_t entries = 0;
  for (const auto& entry : std::filesystem::directory_iterator(fs.path())) {
    EXPECT_EQ(entry.path().filename(), "map.mlndtmap");
    ++entries;
  }
  EXPECT_EQ(entries, 1u);
  std::filesystem::remove(path);
  EXPECT_EQ(fs.FreeBytes(), free_at_start);
}

// A map small enough to sit in a stream buffer until close(): the failure
// shows up only when the file is closed.
TEST(SaveLayeredGrid, DiskFullAtCloseKeepsThePreviousMap) {
  testing::SmallFileSystem fs;
  MLNDT_MOUNT_SMALL_FS_OR_SKIP(fs, 64 * 1024);
  const std::string path = fs.path() + "/map.mlndtmap";
  const std::string old_bytes = FromHex(kVersion1Map);
  WriteAll(path, old_bytes);
  LayeredGrid small;
  std::string error;
  ASSERT_TRUE(LoadLayeredGrid(path, &small, &error)) << error;
  fs.Fill();
  ASSERT_EQ(fs.FreeBytes(), 0u);
  EXPECT_FALSE(SaveLayeredGrid(path, small, &error));
  EXPECT_NE(error.find(std::strerror(ENOSPC)), std::string::npos) << error;
  EXPECT_EQ(Hex(ReadAll(path)), Hex(old_bytes));
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(fs.path())) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"filler", "map.mlndtmap"}));
}

}  // namespace
}  // namespace mlndt
