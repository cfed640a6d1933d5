#pragma once

// A fixed team of threads that runs slices of one loop and sleeps between
// loops. The Ceres backend's parallel evaluation (point_evaluation_cache.h)
// runs between Ceres' own serial work; OpenMP's threads would spin after
// every loop and, on a machine with more runnable threads than cores, take
// the core the serial work needs (measured 2.5x slower with 2 threads than
// with 1; docs/performance.md). These threads block on a condition variable
// instead.

#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace mlndt {
namespace internal {

class SliceWorkers {
 public:
  // `slices` >= 1: slice 0 runs on the calling thread, slices 1.. on
  // slices - 1 threads started here.
  explicit SliceWorkers(int slices);
  ~SliceWorkers();
  SliceWorkers(const SliceWorkers&) = delete;
  SliceWorkers& operator=(const SliceWorkers&) = delete;

  int slices() const { return slices_; }

  // Calls run(s) for every slice s in [0, slices()), concurrently, and
  // returns when all have returned.
  void Run(const std::function<void(int slice)>& run);

 private:
  void Work(int slice);

  const int slices_;
  std::mutex mutex_;
  std::condition_variable start_;
  std::condition_variable done_;
  const std::function<void(int)>* job_ = nullptr;
  long generation_ = 0;
  int pending_ = 0;
  bool stop_ = false;
  std::vector<std::thread> threads_;
};

}  // namespace internal
}  // namespace mlndt
