// input_prep_benchmark: the per-scan work before the solve, with the
// registration's default options, on one KITTI Velodyne scan (frame 0 of
// sequence 00, data/kitti/pcd/000000.pcd) and its successor:
//
//  - BM_RangeFilter: FilterByRange (RangeFilterOptions defaults);
//  - BM_MapBuild: the reference range filter plus LayeredGrid::Build
//    (Register()'s "map" time);
//  - BM_Sampling: the input range filter plus SamplePoints (GBS 1 m; the
//    "sampling" time);
//  - BM_MatchCell: MatchCell for every sampled point of frame 1 on every
//    layer of frame 0's map, NEAREST_CELL and ZERO_RESIDUAL.
//
//   input_prep_benchmark [--benchmark_filter=...]
//
// Run from the repository root (or set MLNDT_BENCH_SCAN_DIR to a folder
// holding 000000.pcd and 000001.pcd). docs/performance.md has the results.

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <iostream>
#include <string>

#include "mlndt/cloud/io.h"
#include "mlndt/cloud/range_filter.h"
#include "mlndt/cost/cell_match.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/registration/registration_options.h"
#include "mlndt/sampling/point_sampler.h"

namespace mlndt {
namespace {

PointCloud& Scan(int i) {
  static PointCloud scans[2];
  return scans[i];
}

void BM_RangeFilter(benchmark::State& state) {
  const RegistrationOptions options;
  for (auto _ : state) {
    PointCloud kept = FilterByRange(options.range_filter, Scan(0), nullptr);
    benchmark::DoNotOptimize(kept);
  }
}
BENCHMARK(BM_RangeFilter)->Unit(benchmark::kMillisecond);

void BM_MapBuild(benchmark::State& state) {
  const RegistrationOptions options;
  std::string error;
  for (auto _ : state) {
    const PointCloud kept =
        FilterByRange(options.range_filter, Scan(0), nullptr);
    LayeredGrid map;
    if (!LayeredGrid::Build(options.grid, kept, &map, &error)) {
      state.SkipWithError(error.c_str());
      return;
    }
    benchmark::DoNotOptimize(map);
  }
}
BENCHMARK(BM_MapBuild)->Unit(benchmark::kMillisecond);

void BM_Sampling(benchmark::State& state) {
  const RegistrationOptions options;
  std::string error;
  for (auto _ : state) {
    const PointCloud kept =
        FilterByRange(options.range_filter, Scan(1), nullptr);
    PointCloud sampled;
    if (!SamplePoints(options.sampling, kept, &sampled, nullptr, &error)) {
      state.SkipWithError(error.c_str());
      return;
    }
    benchmark::DoNotOptimize(sampled);
  }
}
BENCHMARK(BM_Sampling)->Unit(benchmark::kMillisecond);

void BM_MatchCell(benchmark::State& state) {
  const RegistrationOptions options;
  const UnmatchedPolicy policy = state.range(0) == 0
                                     ? UnmatchedPolicy::ZERO_RESIDUAL
                                     : UnmatchedPolicy::NEAREST_CELL;
  std::string error;
  LayeredGrid map;
  PointCloud sampled;
  if (!LayeredGrid::Build(options.grid,
                          FilterByRange(options.range_filter, Scan(0), nullptr),
                          &map,
                          &error) ||
      !SamplePoints(options.sampling,
                    FilterByRange(options.range_filter, Scan(1), nullptr),
                    &sampled,
                    nullptr,
                    &error)) {
    state.SkipWithError(error.c_str());
    return;
  }
  int64_t matched = 0;
  for (auto _ : state) {
    for (int l = 1; l <= map.num_layers(); ++l) {
      for (const Eigen::Vector3d& p : sampled.points()) {
        matched += MatchCell(map.layer(l), p, policy) != nullptr;
      }
    }
  }
  benchmark::DoNotOptimize(matched);
  state.SetItemsProcessed(state.iterations() * map.num_layers() *
                          static_cast<int64_t>(sampled.size()));
}
BENCHMARK(BM_MatchCell)
    ->ArgName("nearest_cell")
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace mlndt

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  const char* dir_env = std::getenv("MLNDT_BENCH_SCAN_DIR");
  const std::string dir =
      dir_env != nullptr && *dir_env != '\0' ? dir_env : "data/kitti/pcd";
  for (int i = 0; i < 2; ++i) {
    const std::string path = dir + "/00000" + std::to_string(i) + ".pcd";
    std::string error;
    if (!mlndt::ReadPointCloud(path, &mlndt::Scan(i), nullptr, &error)) {
      std::cerr << "input_prep_benchmark: " << error << std::endl;
      return 1;
    }
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
