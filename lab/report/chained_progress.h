#pragma once

// The progress of consecutive loops (a suite's data sets, an experiment's
// jobs) reported as one loop: each loop's events numbered across all of
// them, each status led by the loop's name. The printer is the caller's
// (tools/cli/progress_printer.h).

#include <string>

#include "mlndt/common/progress.h"

namespace mlndt {

class ChainedProgress : public ProgressCallback {
 public:
  // `progress` (may be null, not owned) hears of `total` items in all.
  ChainedProgress(ProgressCallback* progress, size_t total)
      : progress_(progress), total_(total) {}

  // The loop whose events come next, named `name`.
  void Next(std::string name) {
    name_ = std::move(name);
    offset_ = done_;
  }

  void operator()(const ProgressEvent& event) override {
    done_ = offset_ + event.done;
    ReportProgress(progress_,
                   {offset_ + event.index,
                    done_,
                    total_,
                    name_ + (event.status.empty() ? "" : " " + event.status)});
  }

 private:
  ProgressCallback* progress_;
  size_t total_ = 0;
  size_t offset_ = 0;
  size_t done_ = 0;
  std::string name_;
};

}  // namespace mlndt
