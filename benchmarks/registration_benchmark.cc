// Registration cost per pair on the bundled real scans, by backend: the
// KITTI 00 pair 0 -> 1 and the koide3 Velodyne pair. Options are the
// defaults, changed by the registration flags of the tools (e.g.
// --gbs_cell_size_m=2); --backend is overridden per benchmark. CPU time is the
// figure to compare (the machine is shared).

#include <benchmark/benchmark.h>
#include <glog/logging.h>

#include <string>

#include "mlndt/cloud/io.h"
#include "mlndt/registration/registration.h"
#include "tools/cli/registration_flags.h"

namespace mlndt {
namespace {

struct Pair {
  PointCloud reference, input;
};

Pair Load(const std::string& reference, const std::string& input) {
  Pair pair;
  std::string error;
  const std::string dir = MLNDT_DATA_DIR;
  CHECK(ReadPointCloud(dir + "/" + reference, &pair.reference, nullptr, &error))
      << error;
  CHECK(ReadPointCloud(dir + "/" + input, &pair.input, nullptr, &error))
      << error;
  return pair;
}

const Pair& Kitti() {
  static const Pair pair = Load("kitti/pcd/000000.pcd", "kitti/pcd/000001.pcd");
  return pair;
}

const Pair& Koide3() {
  static const Pair pair = Load("koide3/251370668.pcd", "koide3/251371071.pcd");
  return pair;
}

void Run(benchmark::State& state, const Pair& pair) {
  RegistrationOptions options;
  std::string error;
  CHECK(tools::RegistrationOptionsFromFlags(&options, &error)) << error;
  constexpr BackendType kBackends[] = {BackendType::CERES,
                                       BackendType::NEWTON,
                                       BackendType::LEVENBERG_MARQUARDT};
  options.backend.type = kBackends[state.range(0)];
  RegistrationSummary summary;
  for (auto _ : state) {
    Register(
        options, pair.reference, pair.input, Isometry3d::Identity(), &summary);
    CHECK(summary.IsSolutionUsable()) << summary.message;
  }
  state.SetLabel(BackendTypeToString(options.backend.type));
  state.counters["iterations"] = summary.num_iterations;
  state.counters["sampled"] = static_cast<double>(summary.sampled_points);
  state.counters["map_ms"] = summary.map_time_s * 1e3;
  state.counters["solve_ms"] = summary.solve_time_s * 1e3;
}

void BM_RegisterKitti(benchmark::State& state) { Run(state, Kitti()); }
void BM_RegisterKoide3(benchmark::State& state) { Run(state, Koide3()); }

BENCHMARK(BM_RegisterKitti)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RegisterKoide3)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace mlndt

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  gflags::ParseCommandLineFlags(&argc, &argv, true);
  benchmark::RunSpecifiedBenchmarks();
  return 0;
}
