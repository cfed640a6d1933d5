#include "lab/bench/bench.h"

#include <memory>

#include "lab/bench/bench_option_tables.h"
#include "lab/bench/pcl_methods.h"

namespace mlndt {
namespace {

bool CheckOptions(const BenchOptions& options, std::string* error) {
  // The ranges of BenchOptionsTable (the PCL settings' among them).
  if (!BenchOptionsTable().Check(options, error)) return false;
  if ((options.compare_pcl_ndt || options.compare_pcl_gicp) &&
      !PclAvailable()) {
    *error = std::string(options.compare_pcl_ndt ? "--compare_pcl_ndt"
                                                 : "--compare_pcl_gicp") +
             ": this build has no PCL; configure with -DMLNDT_WITH_PCL=ON";
    return false;
  }
  return true;
}

std::vector<std::unique_ptr<BenchMethod>> MakeMethods(
    const BenchOptions& options,
    const std::vector<BenchConfiguration>& configurations) {
  std::vector<std::unique_ptr<BenchMethod>> methods;
  for (const BenchConfiguration& c : configurations) {
    methods.push_back(std::make_unique<MlndtBenchMethod>(c, options.grid.seed));
  }
  if (options.compare_pcl_ndt) methods.push_back(MakePclNdtMethod(options.pcl));
  if (options.compare_pcl_gicp) {
    methods.push_back(MakePclGicpMethod(options.pcl));
  }
  return methods;
}

}  // namespace

bool RunBench(const BenchOptions& options,
              BenchResult* result,
              std::string* error) {
  std::vector<BenchConfiguration> configurations;
  std::vector<ScanPair> pairs;
  if (!CheckOptions(options, error) ||
      !ParseBenchConfigurations(options.grid, &configurations, error) ||
      !LoadBenchPairs(options.pairs, &pairs, error)) {
    return false;
  }
  if (options.one_shot) {
    const size_t warm = pairs.size();
    for (size_t p = 0; p < warm; ++p) {
      pairs.push_back(pairs[p]);
      pairs.back().set += " one-shot";
      pairs.back().one_shot = true;
    }
  }
  const std::vector<std::unique_ptr<BenchMethod>> methods =
      MakeMethods(options, configurations);
  *result = BenchResult();
  result->num_configurations = configurations.size();
  for (const auto& method : methods) {
    if (!method->Prepare(pairs, error)) return false;
    result->methods.push_back(method->Labels());
  }
  const auto runs = RunBenchRounds(options.rounds, methods, pairs);
  result->sets = BenchSets(pairs);
  for (const std::string& set : result->sets) {
    std::vector<size_t> indices;
    for (size_t p = 0; p < pairs.size(); ++p) {
      if (pairs[p].set == set) indices.push_back(p);
    }
    result->set_pairs.push_back(indices.size());
    result->stats.emplace_back();
    for (const auto& method_runs : runs) {
      result->stats.back().push_back(SummariseRuns(method_runs, indices));
    }
  }
  return true;
}

}  // namespace mlndt
