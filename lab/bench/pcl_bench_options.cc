#include "lab/bench/pcl_bench_options.h"

#include "lab/bench/bench_option_tables.h"

namespace mlndt {

bool PclBenchOptions::IsValid(std::string* error) const {
  return PclBenchOptionsTable().Check(*this, error);
}

}  // namespace mlndt
