#pragma once

// The progress of every tool's loop on stderr: the library's loops report
// through a ProgressCallback (mlndt/common/progress.h) and this one prints
// it. A bar redrawn in place with the elapsed time and an ETA when stderr
// is a terminal; one plain line per item otherwise (logs, pipes, CI):
//
//   mlndt_localize 8/8 000007.pcd CONVERGENCE, inliers 0.959, ... [23 s, ETA 0
//   s]

#include <chrono>
#include <string>
#include <vector>

#include "mlndt/common/progress.h"

namespace mlndt {
namespace tools {

class ProgressPrinter : public ProgressCallback {
 public:
  // `label` leads every line. With `item_names`, the line of item i names
  // it (item_names[i]) before its status.
  explicit ProgressPrinter(std::string label,
                           std::vector<std::string> item_names = {});
  ~ProgressPrinter() override { Finish(); }

  void operator()(const ProgressEvent& event) override;

  // Ends the bar's line (idempotent); the next output starts on its own.
  void Finish();

 private:
  // "[12 s, ETA 30 s]": the elapsed time and the rest at the mean pace.
  std::string Times(size_t done, size_t total) const;

  std::string label_;
  std::vector<std::string> item_names_;
  bool terminal_ = false;
  bool open_line_ = false;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace tools
}  // namespace mlndt
