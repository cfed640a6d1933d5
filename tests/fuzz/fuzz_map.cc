// libFuzzer target: map files (LoadLayeredGrid on a scratch file). The
// input is the file WITHOUT its last 8 bytes: the target appends the FNV-1a
// checksum, so that mutations reach the header and cell checks behind it (a
// valid checksum is no protection: anyone can compute one). A map that loads
// is saved and loaded again and must come back with the same layers, keys,
// counts and means.
// Seeds: tests/fuzz/corpus/map/ (bodies). Run by .ci/fuzz.

#include "mlndt/grid/grid_io.h"
#include "tests/fuzz/fuzz_common.h"

namespace {

std::string WithChecksum(std::string body) {
  uint64_t hash = 14695981039346656037ull;
  for (unsigned char c : body) {
    hash ^= c;
    hash *= 1099511628211ull;
  }
  for (int i = 0; i < 8; ++i)
    body.push_back(static_cast<char>(hash >> (8 * i)));
  return body;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* bytes, size_t size) {
  static const std::string path = mlndt::fuzz::ScratchPath("map.mlndtmap");
  static const std::string again_path =
      mlndt::fuzz::ScratchPath("map_again.mlndtmap");
  mlndt::fuzz::WriteScratch(
      path,
      WithChecksum(std::string(reinterpret_cast<const char*>(bytes), size)));
  mlndt::LayeredGrid grid;
  std::string error;
  if (!mlndt::LoadLayeredGrid(path, &grid, &error)) {
    MLNDT_FUZZ_CHECK(grid.empty() && !error.empty());
    return 0;
  }
  MLNDT_FUZZ_CHECK(mlndt::SaveLayeredGrid(again_path, grid, &error));
  mlndt::LayeredGrid again;
  if (!mlndt::LoadLayeredGrid(again_path, &again, &error)) {
    std::fprintf(stderr, "reload failed: %s\n", error.c_str());
    std::abort();
  }
  MLNDT_FUZZ_CHECK(again.num_layers() == grid.num_layers());
  MLNDT_FUZZ_CHECK(again.num_points() == grid.num_points());
  for (int i = 1; i <= grid.num_layers(); ++i) {
    const mlndt::NdtLayer& a = grid.layer(i);
    const mlndt::NdtLayer& b = again.layer(i);
    MLNDT_FUZZ_CHECK(a.dims() == b.dims() && a.keys() == b.keys());
    for (size_t c = 0; c < a.cells().size(); ++c) {
      MLNDT_FUZZ_CHECK(a.cells()[c].count == b.cells()[c].count);
      MLNDT_FUZZ_CHECK(a.cells()[c].mean == b.cells()[c].mean);
    }
  }
  return 0;
}
