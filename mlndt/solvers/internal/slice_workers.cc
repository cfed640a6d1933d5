#include "mlndt/solvers/internal/slice_workers.h"

#include <glog/logging.h>

namespace mlndt {
namespace internal {

SliceWorkers::SliceWorkers(int slices) : slices_(slices) {
  CHECK_GE(slices_, 1);
  for (int s = 1; s < slices_; ++s) {
    threads_.emplace_back([this, s] { Work(s); });
  }
}

SliceWorkers::~SliceWorkers() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  start_.notify_all();
  for (std::thread& thread : threads_) thread.join();
}

void SliceWorkers::Run(const std::function<void(int)>& run) {
  if (slices_ > 1) {
    std::lock_guard<std::mutex> lock(mutex_);
    job_ = &run;
    pending_ = slices_ - 1;
    ++generation_;
  }
  start_.notify_all();
  run(0);
  if (slices_ == 1) return;
  std::unique_lock<std::mutex> lock(mutex_);
  done_.wait(lock, [this] { return pending_ == 0; });
  job_ = nullptr;
}

void SliceWorkers::Work(int slice) {
  long seen = 0;
  while (true) {
    const std::function<void(int)>* job = nullptr;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      start_.wait(lock, [&] { return stop_ || generation_ != seen; });
      if (stop_) return;
      seen = generation_;
      job = job_;
    }
    (*job)(slice);
    bool last = false;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      last = --pending_ == 0;
    }
    if (last) done_.notify_one();
  }
}

}  // namespace internal
}  // namespace mlndt
