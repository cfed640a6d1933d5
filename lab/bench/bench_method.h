#pragma once

// A method mlndt_bench times: one of our configurations
// (MlndtBenchMethod) or a peer (lab/bench/pcl_methods.h). The runner
// (lab/bench/bench_rounds.h) calls Prepare once, untimed, then Run for every
// pair in every round; the method times itself (everything after loading).

#include <memory>
#include <string>
#include <vector>

#include "lab/bench/bench_configurations.h"
#include "lab/bench/bench_pairs.h"
#include "lab/bench/bench_run.h"

namespace mlndt {

// How a row names its method (empty: does not apply).
struct BenchMethodLabels {
  std::string method = "pcl_ndt";  // mlndt, pcl_ndt, pcl_gicp.
  std::string defaults, backend, sampling, start, solver, region;
  std::string minimizer, jacobians, loss;  // loss: "cauchy@1.5", "none".
  std::string threads = "1";
  bool is_pcl = true;
};

class BenchMethod {
 public:
  virtual ~BenchMethod() = default;
  virtual BenchMethodLabels Labels() const = 0;
  // Once before the rounds, outside the timing (e.g. converting clouds).
  // False with *error when the method cannot run on `pairs`.
  virtual bool Prepare(const std::vector<ScanPair>& pairs, std::string* error);
  // Registers pairs[pair_index] (the pairs of Prepare) from its start.
  virtual BenchEstimate Run(size_t pair_index, const ScanPair& pair) = 0;
};

// mlndt::Register with one configuration of the grid.
class MlndtBenchMethod : public BenchMethod {
 public:
  MlndtBenchMethod(const BenchConfiguration& configuration, uint64_t seed);
  BenchMethodLabels Labels() const override;
  BenchEstimate Run(size_t pair_index, const ScanPair& pair) override;

 private:
  BenchConfiguration configuration_;
  RegistrationOptions options_;
};

// The labels of a configuration's row.
BenchMethodLabels ConfigurationLabels(const BenchConfiguration& c);

// The configuration in one short line (plots): backend, minimizer,
// Jacobians, loss, linear solver, trust region, sampling, start layer,
// threads, without the parts that do not apply; a peer's method name.
std::string ShortLabel(const BenchMethodLabels& labels);

// `value` printed with `format`; "-" when not finite.
std::string BenchFormat(const char* format, double value);

}  // namespace mlndt
