// pcl::NormalDistributionsTransform and mlndt::pcl::MultiLayerNdt on the
// pairs of data folders with a reference_pairs.json, from the identity and
// from a far start (5 m along the reference frame's x and 30 deg of yaw,
// applied as offset ∘ reference), each through the same pcl::Registration
// calls:
//   pcl_ndt      PCL's NDT as its tutorial configures it: resolution 1 m,
//                step 0.1, epsilon 0.01, 35 iterations, the input thinned
//                by a 0.2 m ApproximateVoxelGrid. (PCL 1.13 stops when a
//                step's squared translation is <= epsilon, and the step
//                size bounds a step's length: it stops after one step.)
//   pcl_ndt_eps  The same with epsilon 1e-6 (steps of 1 mm).
//   mlndt        MultiLayerNdt with mlndt's defaults, on the whole input.
//   mlndt_swap   MultiLayerNdt with the tutorial's calls and thinned input
//                (the tutorial with only the type changed).
// A fresh object per run: the time [ms] covers setInputTarget, setInputSource
// and align (the target's grid or map and PCL's k-d tree included; the
// voxel filter not). Right = within 0.2 m and 1 deg of the reference.
//
//   pcl_ndt_compare [--csv=FILE] DIR...
//
// A pair "a_b" of DIR/reference_pairs.json registers the input b onto the
// reference a, read from DIR/pcd/<a as 6 digits>.pcd (KITTI),
// DIR/<a>.pcd (koide3) or DIR/room_scan<a>.pcd (PCL's room scans). Prints
// one summary row per (folder, start, method) as a Markdown table; --csv
// writes every run.

#include <pcl/filters/approximate_voxel_grid.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>
#include <pcl/registration/ndt.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "mlndt/pcl/multi_layer_ndt.h"

namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;
constexpr double kPi = 3.14159265358979323846;

struct Pair {
  std::string folder, key, reference_path, input_path;
  Eigen::Matrix4d reference = Eigen::Matrix4d::Identity();
};

struct Run {
  std::string folder, key, start, method;
  double error_m = 0.0, error_deg = 0.0, time_ms = 0.0;
  int iterations = 0;
  bool converged = false;
  std::string verdict;  // mlndt's termination type; "-" for PCL's NDT.
  bool right() const { return error_m <= 0.2 && error_deg <= 1.0; }
};

bool FileExists(const std::string& path) { return std::ifstream(path).good(); }

// The scan named `id` in `dir` (see the header comment); "" if none.
std::string ScanPath(const std::string& dir, const std::string& id) {
  char kitti[16];
  std::snprintf(kitti, sizeof(kitti), "%06d", std::atoi(id.c_str()));
  for (const std::string& path : {dir + "/pcd/" + kitti + ".pcd",
                                  dir + "/" + id + ".pcd",
                                  dir + "/room_scan" + id + ".pcd"}) {
    if (FileExists(path)) return path;
  }
  return "";
}

bool ReadPairs(const std::string& dir, std::vector<Pair>* pairs) {
  std::ifstream file(dir + "/reference_pairs.json");
  if (!file) return false;
  const nlohmann::ordered_json json = nlohmann::ordered_json::parse(file);
  std::string folder = dir.substr(dir.find_last_of('/') + 1);
  for (const auto& [key, entry] : json.items()) {
    Pair pair;
    pair.folder = folder;
    pair.key = key;
    const size_t split = key.find('_');
    pair.reference_path = ScanPath(dir, key.substr(0, split));
    pair.input_path = ScanPath(dir, key.substr(split + 1));
    if (pair.reference_path.empty() || pair.input_path.empty()) return false;
    const std::vector<double> m = entry["reference_from_input"];
    for (int i = 0; i < 12; ++i) pair.reference(i / 4, i % 4) = m[i];
    pairs->push_back(pair);
  }
  return true;
}

// offset ∘ reference: 5 m along x, 30 deg about z.
Eigen::Matrix4f FarStart(const Eigen::Matrix4d& reference) {
  const Eigen::Matrix4d offset =
      (Eigen::Translation3d(5.0, 0.0, 0.0) *
       Eigen::AngleAxisd(30.0 * kPi / 180.0, Eigen::Vector3d::UnitZ()))
          .matrix();
  return (offset * reference).cast<float>();
}

void Errors(const Eigen::Matrix4f& result,
            const Eigen::Matrix4d& truth,
            Run* run) {
  const Eigen::Matrix4d delta = truth.inverse() * result.cast<double>();
  run->error_m =
      (result.cast<double>().block<3, 1>(0, 3) - truth.block<3, 1>(0, 3))
          .norm();
  const double cos_angle =
      std::clamp((delta.block<3, 3>(0, 0).trace() - 1.0) / 2.0, -1.0, 1.0);
  run->error_deg = std::acos(cos_angle) * 180.0 / kPi;
}

double Ms(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double, std::milli>(
             std::chrono::steady_clock::now() - since)
      .count();
}

// The tutorial's calls on `ndt` (either type).
template <typename Ndt>
void ConfigureAsTutorial(Ndt* ndt) {
  ndt->setTransformationEpsilon(0.01);
  ndt->setStepSize(0.1);
  ndt->setResolution(1.0);
  ndt->setMaximumIterations(35);
}

template <typename Ndt>
void Align(Ndt* ndt,
           const Cloud::Ptr& target,
           const Cloud::Ptr& source,
           const Eigen::Matrix4f& guess,
           const Eigen::Matrix4d& truth,
           Run* run) {
  Cloud aligned;
  const auto t0 = std::chrono::steady_clock::now();
  ndt->setInputTarget(target);
  ndt->setInputSource(source);
  ndt->align(aligned, guess);
  run->time_ms = Ms(t0);
  run->converged = ndt->hasConverged();
  run->iterations = ndt->getFinalNumIteration();
  Errors(ndt->getFinalTransformation(), truth, run);
}

std::vector<Run> RunPair(const Pair& pair) {
  Cloud::Ptr target(new Cloud), source(new Cloud), thinned(new Cloud);
  if (pcl::io::loadPCDFile(pair.reference_path, *target) != 0 ||
      pcl::io::loadPCDFile(pair.input_path, *source) != 0) {
    return {};
  }
  pcl::ApproximateVoxelGrid<pcl::PointXYZ> voxel_filter;
  voxel_filter.setLeafSize(0.2, 0.2, 0.2);
  voxel_filter.setInputCloud(source);
  voxel_filter.filter(*thinned);
  std::vector<Run> runs;
  for (const bool far : {false, true}) {
    const Eigen::Matrix4f guess =
        far ? FarStart(pair.reference) : Eigen::Matrix4f::Identity();
    Run run{pair.folder, pair.key, far ? "5m_30deg" : "identity"};
    run.method = "pcl_ndt";
    run.verdict = "-";
    pcl::NormalDistributionsTransform<pcl::PointXYZ, pcl::PointXYZ> ndt;
    ConfigureAsTutorial(&ndt);
    Align(&ndt, target, thinned, guess, pair.reference, &run);
    runs.push_back(run);

    run.method = "pcl_ndt_eps";
    pcl::NormalDistributionsTransform<pcl::PointXYZ, pcl::PointXYZ> tight;
    ConfigureAsTutorial(&tight);
    tight.setTransformationEpsilon(1e-6);
    Align(&tight, target, thinned, guess, pair.reference, &run);
    runs.push_back(run);

    run.method = "mlndt";
    mlndt::pcl::MultiLayerNdt<pcl::PointXYZ, pcl::PointXYZ> mlndt;
    Align(&mlndt, target, source, guess, pair.reference, &run);
    run.verdict = TerminationTypeToString(mlndt.getTerminationType());
    runs.push_back(run);

    run.method = "mlndt_swap";
    mlndt::pcl::MultiLayerNdt<pcl::PointXYZ, pcl::PointXYZ> swapped;
    ConfigureAsTutorial(&swapped);
    Align(&swapped, target, thinned, guess, pair.reference, &run);
    run.verdict = TerminationTypeToString(swapped.getTerminationType());
    runs.push_back(run);
  }
  return runs;
}

double Median(std::vector<double> values) {
  if (values.empty()) return NAN;
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// One Markdown row per (folder, start, method), in the order first seen.
void PrintSummary(const std::vector<Run>& runs) {
  std::printf(
      "| folder | start | method | runs | right | hasConverged | converged "
      "but wrong | median error m / deg | max error m | verdicts | median "
      "iterations | median time ms |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::vector<std::string> order;
  std::map<std::string, std::vector<const Run*>> groups;
  for (const Run& run : runs) {
    const std::string id = run.folder + "|" + run.start + "|" + run.method;
    if (!groups.count(id)) order.push_back(id);
    groups[id].push_back(&run);
  }
  for (const std::string& id : order) {
    const std::vector<const Run*>& group = groups[id];
    int right = 0, converged = 0, wrong_converged = 0;
    std::vector<double> m, deg, ms, iterations;
    std::map<std::string, int> verdicts;
    for (const Run* run : group) {
      right += run->right();
      converged += run->converged;
      wrong_converged += run->converged && !run->right();
      m.push_back(run->error_m);
      deg.push_back(run->error_deg);
      ms.push_back(run->time_ms);
      iterations.push_back(run->iterations);
      ++verdicts[run->verdict];
    }
    std::string verdict_text;
    for (const auto& [verdict, count] : verdicts) {
      if (verdict == "-") continue;
      verdict_text += (verdict_text.empty() ? "" : ", ") + verdict + " " +
                      std::to_string(count);
    }
    const Run& first = *group.front();
    std::printf(
        "| %s | %s | %s | %zu | %d | %d | %d | %.3f / %.2f | %.2f | %s | %.0f "
        "| %.0f |\n",
        first.folder.c_str(),
        first.start.c_str(),
        first.method.c_str(),
        group.size(),
        right,
        converged,
        wrong_converged,
        Median(m),
        Median(deg),
        *std::max_element(m.begin(), m.end()),
        verdict_text.empty() ? "-" : verdict_text.c_str(),
        Median(iterations),
        Median(ms));
  }
}

void WriteCsv(const std::string& path, const std::vector<Run>& runs) {
  std::ofstream csv(path);
  csv << "folder,pair,start,method,error_m,error_deg,has_converged,verdict,"
         "iterations,time_ms\n";
  for (const Run& r : runs) {
    csv << r.folder << "," << r.key << "," << r.start << "," << r.method << ","
        << r.error_m << "," << r.error_deg << "," << r.converged << ","
        << r.verdict << "," << r.iterations << "," << r.time_ms << "\n";
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::string csv_path;
  std::vector<std::string> dirs;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.rfind("--csv=", 0) == 0) {
      csv_path = arg.substr(6);
    } else {
      dirs.push_back(arg);
    }
  }
  if (dirs.empty()) {
    std::cerr << "usage: pcl_ndt_compare [--csv=FILE] DIR...\n";
    return 2;
  }
  std::vector<Pair> pairs;
  for (const std::string& dir : dirs) {
    if (!ReadPairs(dir, &pairs)) {
      std::cerr << dir << ": no reference_pairs.json, or a scan is missing\n";
      return 2;
    }
  }
  std::vector<Run> runs;
  for (const Pair& pair : pairs) {
    const std::vector<Run> pair_runs = RunPair(pair);
    if (pair_runs.empty()) {
      std::cerr << pair.reference_path << ", " << pair.input_path
                << ": cannot read\n";
      return 2;
    }
    runs.insert(runs.end(), pair_runs.begin(), pair_runs.end());
  }
  PrintSummary(runs);
  if (!csv_path.empty()) WriteCsv(csv_path, runs);
  return 0;
}
