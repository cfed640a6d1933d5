// map_benchmark: time to build the layered NDT map (LayeredGrid::Build) and
// to sample the source scan (SamplePoints) on one KITTI Velodyne scan
// (frame 0 of sequence 00, 124668 points).
//
//   map_benchmark [--benchmark_filter=...] [--benchmark_min_time=0.2]
//
// The map builds run with threads = LayeredGridOptions::num_threads = 1 and
// 2 and are timed in wall-clock time (UseRealTime). OpenMP's idle threads
// spin-wait by default; on a loaded machine compare with
// OMP_WAIT_POLICY=passive map_benchmark ...
//
// The scan is the first of these that is set / exists:
//   1. $MLNDT_BENCH_SCAN (any format mlndt reads; an error if missing),
//   2. data/kitti/pcd/000000.pcd below the current folder,
//   3. data/kitti/pcd/000000.pcd of the repository, when the binary sits in
//      <repo>/<build>/benchmarks/,
//   4. $MLNDT_DATA_DIR/kitti00_frames_0000_0007/pcd/000000.pcd.
//
// items_per_second is input points per second. map_bytes is
// LayeredGrid::MemoryBytes() and bytes_per_cell that over the occupied cells
// of all layers.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <system_error>
#include <vector>

#include "mlndt/cloud/io.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/sampling/point_sampler.h"

namespace mlndt {
namespace {

constexpr char kBundledScan[] = "data/kitti/pcd/000000.pcd";
constexpr char kSharedScan[] = "kitti00_frames_0000_0007/pcd/000000.pcd";

// The scan every benchmark uses; loaded by main() before they run.
PointCloud& Scan() {
  static PointCloud scan;
  return scan;
}

// Candidate paths in order of preference (see the file comment). With
// MLNDT_BENCH_SCAN set, it is the only candidate.
std::vector<std::string> ScanCandidates() {
  if (const char* scan = std::getenv("MLNDT_BENCH_SCAN");
      scan != nullptr && *scan != '\0') {
    return {scan};
  }
  std::vector<std::string> candidates = {kBundledScan};
  std::error_code error;
  const std::filesystem::path binary =
      std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) {
    candidates.push_back(
        (binary.parent_path().parent_path().parent_path() / kBundledScan)
            .lexically_normal());
  }
  if (const char* dir = std::getenv("MLNDT_DATA_DIR");
      dir != nullptr && *dir != '\0') {
    candidates.push_back(std::string(dir) + "/" + kSharedScan);
  }
  return candidates;
}

// Loads the first existing candidate into Scan(); false with *error.
bool LoadScan(std::string* path, std::string* error) {
  const std::vector<std::string> candidates = ScanCandidates();
  for (const std::string& candidate : candidates) {
    std::error_code exists_error;
    if (candidates.size() > 1 &&
        !std::filesystem::exists(candidate, exists_error))
      continue;
    *path = candidate;
    return ReadPointCloud(candidate, &Scan(), nullptr, error);
  }
  *error = "no KITTI scan found; tried:";
  for (const std::string& candidate : candidates) *error += "\n  " + candidate;
  *error +=
      "\nset MLNDT_BENCH_SCAN to a scan file, or MLNDT_DATA_DIR to the shared "
      "data folder";
  return false;
}

// Builds the map once per iteration and reports the finest layer.
void RunBuild(const LayeredGridOptions& options,
              int threads,
              benchmark::State& state) {
  const PointCloud& scan = Scan();
  LayeredGrid grid;
  std::string error;
  for (auto _ : state) {
    LayeredGrid built;
    if (!LayeredGrid::Build(options, scan, threads, &built, &error)) {
      state.SkipWithError(error.c_str());
      return;
    }
    benchmark::DoNotOptimize(built);
    grid = std::move(built);
  }
  state.SetItemsProcessed(state.iterations() *
                          static_cast<int64_t>(scan.size()));
  const LayerInfo& finest = grid.layer_info().back();
  size_t occupied = 0;
  for (const LayerInfo& info : grid.layer_info())
    occupied += info.occupied_cells;
  state.counters["layers"] = grid.num_layers();
  state.counters["finest_cell_m"] = finest.cell_size_m;
  state.counters["finest_occupied"] =
      static_cast<double>(finest.occupied_cells);
  state.counters["map_bytes"] = static_cast<double>(grid.MemoryBytes());
  state.counters["bytes_per_cell"] =
      static_cast<double>(grid.MemoryBytes()) /
      static_cast<double>(std::max<size_t>(occupied, 1));
}

// Paper sizing (q = 8) with n = state.range(0) layers, state.range(1) threads.
void BM_BuildLayeredGrid(benchmark::State& state) {
  LayeredGridOptions options = PaperLayeredGridOptions();
  options.num_layers = static_cast<int>(state.range(0));
  RunBuild(options, static_cast<int>(state.range(1)), state);
}
BENCHMARK(BM_BuildLayeredGrid)
    ->ArgNames({"num_layers", "threads"})
    ->ArgsProduct({benchmark::CreateDenseRange(2, 6, 1), {1, 2}})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

// As many layers as a finest cell edge of state.range(0) millimetres needs,
// state.range(1) threads.
void BM_BuildLayeredGridFinestCell(benchmark::State& state) {
  LayeredGridOptions options;
  options.finest_cell_size_m = static_cast<double>(state.range(0)) / 1000.0;
  RunBuild(options, static_cast<int>(state.range(1)), state);
}
BENCHMARK(BM_BuildLayeredGridFinestCell)
    ->ArgNames({"finest_mm", "threads"})
    ->ArgsProduct({{4000, 2000, 1000, 500}, {1, 2}})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

void BM_SamplePoints(benchmark::State& state, SamplingOptions options) {
  const PointCloud& scan = Scan();
  PointCloud sampled;
  SamplingSummary summary;
  std::string error;
  for (auto _ : state) {
    if (!SamplePoints(options, scan, &sampled, &summary, &error)) {
      state.SkipWithError(error.c_str());
      return;
    }
    benchmark::DoNotOptimize(sampled);
  }
  state.SetItemsProcessed(state.iterations() *
                          static_cast<int64_t>(scan.size()));
  state.counters["sampled_points"] =
      static_cast<double>(summary.sampled_points);
  if (options.method != SamplingMethod::RANDOM) {
    state.counters["occupied_cells"] =
        static_cast<double>(summary.occupied_cells);
  }
}

SamplingOptions Sampling(SamplingMethod method) {
  SamplingOptions options;
  options.method = method;
  options.random_fraction = 0.15;
  options.voxel_size_m = 0.5;
  return options;
}

BENCHMARK_CAPTURE(BM_SamplePoints, gbs_1m, Sampling(SamplingMethod::GBS))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SamplePoints,
                  random_15pct,
                  Sampling(SamplingMethod::RANDOM))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SamplePoints,
                  voxel_centroid_0_5m,
                  Sampling(SamplingMethod::VOXEL_CENTROID))
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace mlndt

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  std::string path, error;
  if (!mlndt::LoadScan(&path, &error)) {
    std::cerr << "map_benchmark: " << error << std::endl;
    return 1;
  }
  benchmark::AddCustomContext("scan", path);
  benchmark::AddCustomContext("scan_points",
                              std::to_string(mlndt::Scan().size()));
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
