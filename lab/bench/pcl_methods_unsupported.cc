// lab/bench/pcl_methods.h in the build without PCL (MLNDT_WITH_PCL=OFF).

#include "lab/bench/pcl_methods.h"

namespace mlndt {

bool PclAvailable() { return false; }

std::unique_ptr<BenchMethod> MakePclNdtMethod(const PclBenchOptions&) {
  return nullptr;
}

std::unique_ptr<BenchMethod> MakePclGicpMethod(const PclBenchOptions&) {
  return nullptr;
}

}  // namespace mlndt
