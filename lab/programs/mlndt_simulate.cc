// mlndt_simulate: writes simulated LiDAR data sets with exact relative poses
// (lab/sim, docs/simulator.md), one folder per sensor x scene x seed, in
// the shared data sets' format, so mlndt_suite scores them unchanged.
//
//   mlndt_simulate --output_dir=DIR [--sensors=vlp16,hdl64,avia,narrow]
//       [--scenes=street,corridor,rooms,field,vegetation]
//       [--trajectory=auto|car|handheld] [--seeds=1000-1009] [--scans=4]
//       [--steps=1,2,3] [--motion_within_scan] [--car_step_m=1,2]
//
// Seeds 0-999 are for training (choosing thresholds), seeds >= 1000 for
// testing; a number measured on training seeds is not evidence. The same
// flags give byte-identical files. Exit codes: 0 when every set was
// written, 1 when one failed, 2 on bad flags (before any work).

#include <gflags/gflags.h>
#include <glog/logging.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <mutex>
#include <thread>

#include "lab/sim/dataset_files.h"
#include "lab/sim/scenes.h"
#include "lab/sim/seed_list.h"
#include "lab/sim/sensor_model.h"
#include "lab/sim/sim_dataset.h"

// clang-format off
DEFINE_string(output_dir, "", "Folder the data set folders are written into (required)");
DEFINE_string(sensors, "vlp16,hdl64,avia,narrow",
              "Comma-separated sensors: vlp16, hdl32, hdl64, os1_64, os1_128, avia (every "
              "3rd return, keyframe-like), avia_full, narrow");
DEFINE_string(scenes, "street,corridor,rooms,field,vegetation",
              "Comma-separated scenes: street, corridor, tunnel, rooms, stairwell, field, "
              "vegetation");
DEFINE_string(trajectory, "auto",
              "car (1-2 m steps), handheld (0.05-0.6 m, 2-15 deg) or auto (hand-held indoors: "
              "corridor, rooms, stairwell; car elsewhere)");
DEFINE_string(seeds, "1000-1001", "Seeds: a-b ranges and single seeds, comma-separated. "
              "Train 0-999, test >= 1000");
DEFINE_int32(scans, 4, "Scans per data set, in [2, 10000]");
DEFINE_string(steps, "1,2,3", "Pairs i -> i+step for these steps");
DEFINE_bool(motion_within_scan, false,
            "The sensor moves during each sweep (points skewed; per-point times in the PCD)");
DEFINE_string(car_step_m, "", "car: min,max step between scans [m] (default 1,2)");
DEFINE_double(range_sigma_m, -1.0, "When >= 0, replaces every sensor's range noise sigma [m]");
DEFINE_double(dropout, -1.0, "When >= 0, replaces every sensor's dropout probability");
DEFINE_double(beam_offset_deg, 0.0,
              "Diagnostic: when > 0, a spinning sensor's elevations shift in each scan by a "
              "draw in [-this, this] [deg], so two scans' rings do not coincide; in [0, 10]");
DEFINE_int32(threads, 2, "Data sets made at once, in [1, 64]");
// clang-format on

namespace mlndt {
namespace sim {
namespace {

int Refuse(const std::string& message) {
  std::fprintf(stderr, "mlndt_simulate: %s\n", message.c_str());
  return 2;
}

bool ParseSteps(std::vector<int>* steps, std::string* error) {
  std::vector<uint64_t> values;
  if (!ParseSeedList(FLAGS_steps, &values, error)) return false;
  steps->clear();
  for (const uint64_t v : values) {
    if (v < 1 || v > 10000) {
      *error = "a step must be in [1, 10000]";
      return false;
    }
    steps->push_back(static_cast<int>(v));
  }
  return true;
}

bool ParseCarSteps(CarTrajectoryOptions* car, std::string* error) {
  if (FLAGS_car_step_m.empty()) return true;
  double low = 0.0, high = 0.0;
  char extra = 0;
  if (std::sscanf(FLAGS_car_step_m.c_str(), "%lf,%lf%c", &low, &high, &extra) !=
      2) {
    *error = "expected min,max [m]";
    return false;
  }
  car->min_step_m = low;
  car->max_step_m = high;
  return true;
}

// Every combination of the flags, each checked; false with *error naming
// the flag.
bool PlanFromFlags(std::vector<SimulationOptions>* plan, std::string* error) {
  std::vector<std::string> sensors, scenes;
  std::vector<uint64_t> seeds;
  SimulationOptions base;
  if (FLAGS_output_dir.empty()) {
    *error = "--output_dir is required";
    return false;
  }
  const auto flag = [&](const char* name, bool ok) {
    if (!ok) *error = std::string("--") + name + ": " + *error;
    return ok;
  };
  if (!flag("sensors", ParseNameList(FLAGS_sensors, &sensors, error)) ||
      !flag("scenes", ParseNameList(FLAGS_scenes, &scenes, error)) ||
      !flag("seeds", ParseSeedList(FLAGS_seeds, &seeds, error)) ||
      !flag("steps", ParseSteps(&base.steps, error)) ||
      !flag("car_step_m", ParseCarSteps(&base.car, error))) {
    return false;
  }
  if (FLAGS_threads < 1 || FLAGS_threads > 64) {
    *error = "--threads must be in [1, 64]";
    return false;
  }
  base.trajectory = FLAGS_trajectory;
  base.num_scans = FLAGS_scans;
  base.motion_within_scan = FLAGS_motion_within_scan;
  base.range_sigma_m = FLAGS_range_sigma_m;
  base.dropout_probability = FLAGS_dropout;
  base.beam_offset_deg = FLAGS_beam_offset_deg;
  plan->clear();
  for (const uint64_t seed : seeds) {
    for (const std::string& scene : scenes) {
      for (const std::string& sensor : sensors) {
        SimulationOptions options = base;
        options.sensor = sensor;
        options.scene = scene;
        options.seed = seed;
        if (!options.IsValid(error)) return false;
        plan->push_back(options);
      }
    }
  }
  return true;
}

// Makes and writes one set; a line on stdout either way.
bool MakeOne(const SimulationOptions& options, std::mutex* print) {
  const auto start = std::chrono::steady_clock::now();
  const std::string name = SimulationName(options);
  SimDataset dataset;
  std::string error;
  const bool ok =
      MakeSimDataset(options, &dataset, &error) &&
      WriteSimDataset(dataset, FLAGS_output_dir + "/" + name, &error);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
  size_t points = 0, free_pairs = 0;
  for (const SimScan& scan : dataset.scans) points += scan.points.size();
  for (const SimPair& pair : dataset.pairs) {
    free_pairs += pair.constraints.free_directions.empty() ? 0 : 1;
  }
  const std::lock_guard<std::mutex> lock(*print);
  if (!ok) {
    std::fprintf(
        stderr, "mlndt_simulate: %s: %s\n", name.c_str(), error.c_str());
    return false;
  }
  std::printf(
      "%-36s %7zu triangles  %3zu scans  %8zu points  %2zu pairs "
      "(%zu free)  %.2f s\n",
      name.c_str(),
      dataset.scene.mesh.num_triangles(),
      dataset.scans.size(),
      points,
      dataset.pairs.size(),
      free_pairs,
      seconds);
  std::fflush(stdout);
  return true;
}

int Run() {
  std::vector<SimulationOptions> plan;
  std::string error;
  if (!PlanFromFlags(&plan, &error)) return Refuse(error);
  const auto start = std::chrono::steady_clock::now();
  std::atomic<size_t> next{0};
  std::atomic<int> failures{0};
  std::mutex print;
  std::vector<std::thread> workers;
  for (int t = 0; t < FLAGS_threads; ++t) {
    workers.emplace_back([&] {
      for (size_t k = next++; k < plan.size(); k = next++) {
        if (!MakeOne(plan[k], &print)) ++failures;
      }
    });
  }
  for (std::thread& worker : workers) worker.join();
  std::printf(
      "mlndt_simulate: %zu data sets (%d failed) in %s, %.1f s\n",
      plan.size(),
      failures.load(),
      FLAGS_output_dir.c_str(),
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count());
  return failures > 0 ? 1 : 0;
}

}  // namespace
}  // namespace sim
}  // namespace mlndt

int main(int argc, char** argv) {
  gflags::SetUsageMessage(
      "mlndt_simulate --output_dir=DIR [--sensors=...] [--scenes=...] "
      "[--seeds=1000-1009] [--scans=4] (train seeds 0-999, test >= 1000)");
  gflags::ParseCommandLineFlags(&argc, &argv, true);
  google::InitGoogleLogging(argv[0]);
  if (argc > 1) {
    return mlndt::sim::Refuse(std::string("unexpected argument '") + argv[1] +
                              "'");
  }
  return mlndt::sim::Run();
}
