// large_map_benchmark: builds the layered map of a city-block-sized
// synthetic cloud (docs/maps.md): N points over 2 km x 2 km, a 1 m finest
// cell, and compares the cell index's hash table with std::unordered_map.
//
//   large_map_benchmark                                   # 2 M and 20 M
//   large_map_benchmark --benchmark_filter='/2000000'     # quick
//
// The scene (seeded): a ground plane (60 % of the points, 2 cm noise), 5000
// boxes 2-30 m on a side and up to 30 m high (walls and roofs, 30 %), 20000
// poles of 0.15 m radius and up to 8 m (10 %); the points are clamped into
// [0, 2000] x [0, 2000] x [0, 33.554432] m with both corners present, so
// that with q = 8 and --finest_cell_size_m 1 the map has n = 9 layers and
// its finest cell is exactly 1 m (V / 8^9 = 1 m^3).
//
// BM_EstimateLargeMap times EstimateMapMemory (grid/map_memory.h);
// BM_BuildLargeMap times LayeredGrid::Build (one thread) and reports the
// map's bytes, the estimate's, and the process's peak resident memory
// (ru_maxrss, which includes the cloud; run the sizes in ascending order,
// as registered, for it to be the largest build's). One iteration each: a
// 20 M-point build takes tens of seconds and ~3.4 GB.
//
// BM_CellIndexInsert / BM_UnorderedMapInsert: N distinct random keys of the
// 20 M map's finest grid (2001 x 2001 x 34 cells, too many for the dense
// table) into CellIndex and into the std::unordered_map<int64, int32> it
// replaced; bytes is each one's heap estimate (unordered_map: buckets plus
// one 32-byte malloc chunk per node).

#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <unordered_map>
#include <vector>

#include "mlndt/grid/cell_index.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/grid/map_memory.h"

namespace mlndt {
namespace {

constexpr double kSide = 2000.0;            // [m]
constexpr double kHeight = 33.554432;       // [m], 8^9 / kSide^2.
constexpr size_t kLimitBytes = 8000000000;  // Refuse above 8 GB.

double PeakResidentBytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) * 1024.0;
}

PointCloud MakeCityBlock(size_t num_points, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, 0.02);
  const Eigen::Vector3d lo = Eigen::Vector3d::Zero();
  const Eigen::Vector3d hi(kSide, kSide, kHeight);
  std::vector<Eigen::Vector3d> points;
  points.reserve(num_points);
  const auto add = [&](const Eigen::Vector3d& p) {
    points.push_back(p.cwiseMax(lo).cwiseMin(hi));
  };
  add(lo);
  add(hi);
  const size_t ground = num_points * 6 / 10;
  const size_t boxes = num_points * 3 / 10;
  while (points.size() < ground) {
    add({u(rng) * kSide, u(rng) * kSide, std::abs(noise(rng))});
  }
  struct Box {
    double x, y, w, d, h;
  };
  std::vector<Box> box(5000);
  for (Box& b : box) {
    b = {u(rng) * kSide,
         u(rng) * kSide,
         2 + 28 * u(rng),
         2 + 28 * u(rng),
         2 + 28 * u(rng)};
  }
  while (points.size() < ground + boxes) {
    const Box& b = box[rng() % box.size()];
    const double a = u(rng), z = u(rng) * b.h;
    Eigen::Vector3d p;
    switch (rng() % 5) {
      case 0:
        p = {b.x + a * b.w, b.y, z};
        break;
      case 1:
        p = {b.x + a * b.w, b.y + b.d, z};
        break;
      case 2:
        p = {b.x, b.y + a * b.d, z};
        break;
      case 3:
        p = {b.x + b.w, b.y + a * b.d, z};
        break;
      default:  // Roof.
        p = {b.x + a * b.w, b.y + u(rng) * b.d, b.h};
    }
    add(p + Eigen::Vector3d(noise(rng), noise(rng), noise(rng)));
  }
  std::vector<Eigen::Vector2d> poles(20000);
  for (Eigen::Vector2d& q : poles) q = {u(rng) * kSide, u(rng) * kSide};
  while (points.size() < num_points) {
    const Eigen::Vector2d& q = poles[rng() % poles.size()];
    const double angle = 2.0 * M_PI * u(rng);
    add({q.x() + 0.15 * std::cos(angle),
         q.y() + 0.15 * std::sin(angle),
         8.0 * u(rng)});
  }
  return PointCloud(std::move(points));
}

// One cloud at a time (a 20 M cloud is 480 MB).
const PointCloud& CityBlock(size_t num_points) {
  static std::unique_ptr<PointCloud> cloud;
  if (!cloud || cloud->size() != num_points) {
    cloud.reset();
    cloud = std::make_unique<PointCloud>(MakeCityBlock(num_points, 42));
  }
  return *cloud;
}

LayeredGridOptions MapOptions() {
  LayeredGridOptions options;
  options.finest_cell_size_m = 1.0;
  return options;
}

void BM_EstimateLargeMap(benchmark::State& state) {
  const PointCloud& cloud = CityBlock(static_cast<size_t>(state.range(0)));
  MapMemoryEstimate estimate;
  std::string error;
  for (auto _ : state) {
    if (!EstimateMapMemory(
            MapOptions(), cloud, kLimitBytes, &estimate, &error)) {
      state.SkipWithError(error.c_str());
      return;
    }
  }
  state.counters["points"] = static_cast<double>(cloud.size());
  state.counters["layers"] = static_cast<double>(estimate.layers.size());
  state.counters["finest_cell_m"] = estimate.layers.back().cell_size_m;
  state.counters["est_map_bytes"] = static_cast<double>(estimate.map_bytes);
  state.counters["est_total_bytes"] =
      static_cast<double>(estimate.total_bytes());
  state.counters["counting_bytes"] =
      static_cast<double>(estimate.counting_bytes);
}

void BM_BuildLargeMap(benchmark::State& state) {
  const PointCloud& cloud = CityBlock(static_cast<size_t>(state.range(0)));
  MapMemoryEstimate estimate;
  std::string error;
  if (!EstimateMapMemory(MapOptions(), cloud, kLimitBytes, &estimate, &error)) {
    state.SkipWithError(error.c_str());
    return;
  }
  size_t map_bytes = 0, cells = 0, finest_cells = 0;
  for (auto _ : state) {
    LayeredGrid map;
    if (!LayeredGrid::Build(MapOptions(), cloud, &map, &error)) {
      state.SkipWithError(error.c_str());
      return;
    }
    map_bytes = map.MemoryBytes();
    cells = 0;
    for (int i = 1; i <= map.num_layers(); ++i) {
      cells += map.layer(i).cells().size();
    }
    finest_cells = map.layer(map.num_layers()).cells().size();
    state.PauseTiming();
    map = LayeredGrid();  // The free is not timed.
    state.ResumeTiming();
  }
  state.counters["points"] = static_cast<double>(cloud.size());
  state.counters["cells"] = static_cast<double>(cells);
  state.counters["finest_cells"] = static_cast<double>(finest_cells);
  state.counters["map_bytes"] = static_cast<double>(map_bytes);
  state.counters["est_map_bytes"] = static_cast<double>(estimate.map_bytes);
  state.counters["est_total_bytes"] =
      static_cast<double>(estimate.total_bytes());
  state.counters["peak_rss_bytes"] = PeakResidentBytes();
}

// Distinct random keys of the 20 M map's finest grid.
const std::vector<int64_t>& FinestGridKeys(size_t n) {
  static std::vector<int64_t> keys;
  if (keys.size() != n) {
    const int64_t grid_cells = int64_t{2001} * 2001 * 34;
    std::mt19937_64 rng(7);
    keys.clear();
    keys.reserve(n);
    CellIndex seen(grid_cells);
    while (keys.size() < n) {
      const int64_t key = static_cast<int64_t>(rng() % grid_cells);
      if (seen.FindOrInsert(key, static_cast<int32_t>(keys.size())) ==
          static_cast<int32_t>(keys.size())) {
        keys.push_back(key);
      }
    }
  }
  return keys;
}

void BM_CellIndexInsert(benchmark::State& state) {
  const std::vector<int64_t>& keys =
      FinestGridKeys(static_cast<size_t>(state.range(0)));
  size_t bytes = 0;
  for (auto _ : state) {
    CellIndex index(int64_t{2001} * 2001 * 34);
    for (size_t i = 0; i < keys.size(); ++i) {
      index.FindOrInsert(keys[i], static_cast<int32_t>(i));
    }
    int64_t found = 0;
    for (const int64_t key : keys) found += index.Find(key);
    benchmark::DoNotOptimize(found);
    bytes = index.MemoryBytes();
  }
  state.counters["bytes"] = static_cast<double>(bytes);
  state.counters["bytes_per_key"] =
      static_cast<double>(bytes) / static_cast<double>(keys.size());
}

void BM_UnorderedMapInsert(benchmark::State& state) {
  const std::vector<int64_t>& keys =
      FinestGridKeys(static_cast<size_t>(state.range(0)));
  size_t bytes = 0;
  for (auto _ : state) {
    std::unordered_map<int64_t, int32_t> index;
    for (size_t i = 0; i < keys.size(); ++i) {
      index.emplace(keys[i], static_cast<int32_t>(i));
    }
    int64_t found = 0;
    for (const int64_t key : keys) found += index.find(key)->second;
    benchmark::DoNotOptimize(found);
    // Buckets, plus a node (next pointer, key, slot: 24 bytes) in a 32-byte
    // malloc chunk per entry.
    bytes = index.bucket_count() * sizeof(void*) + index.size() * 32;
  }
  state.counters["bytes"] = static_cast<double>(bytes);
  state.counters["bytes_per_key"] =
      static_cast<double>(bytes) / static_cast<double>(keys.size());
}

BENCHMARK(BM_CellIndexInsert)
    ->Arg(7000000)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);
BENCHMARK(BM_UnorderedMapInsert)
    ->Arg(7000000)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);
// Size by size, so that each cloud is generated once.
BENCHMARK(BM_EstimateLargeMap)
    ->Arg(2000000)
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->UseRealTime();
BENCHMARK(BM_BuildLargeMap)
    ->Arg(2000000)
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->UseRealTime();
BENCHMARK(BM_EstimateLargeMap)
    ->Arg(20000000)
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->UseRealTime();
BENCHMARK(BM_BuildLargeMap)
    ->Arg(20000000)
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->UseRealTime();

}  // namespace
}  // namespace mlndt

BENCHMARK_MAIN();
