#pragma once

// Progress of a loop over many items (the map builder's scans, the
// localiser's and the odometry's scans, the lab's pairs and runs), modelled
// on ceres::IterationCallback (include/ceres/iteration_callback.h): the loop
// calls the callback once after each item, in order, with what is done, out
// of how many, and one line on the item. The caller decides where it goes
// (tools/cli/progress_printer.h draws a bar on stderr); the loop's results
// do not depend on it.
//
//   class Counter : public ProgressCallback {
//    public:
//     void operator()(const ProgressEvent& event) override { ++calls; }
//     int calls = 0;
//   };
//   Counter counter;
//   LocalizeScans(options, map, guess, n, load, &counter, &results, &error);

#include <cstddef>
#include <functional>
#include <string>
#include <utility>

namespace mlndt {

struct ProgressEvent {
  size_t index = 0;    // The item just done, in the loop's numbering.
  size_t done = 0;     // Items done, this one included: 1..total.
  size_t total = 0;    // Items the loop will do.
  std::string status;  // One line on the item (its verdict, numbers, time).
};

class ProgressCallback {
 public:
  virtual ~ProgressCallback() = default;
  // Called after each item. Must not throw.
  virtual void operator()(const ProgressEvent& event) = 0;
};

// A ProgressCallback from a function (tests, bindings, lambdas).
class ProgressFunction : public ProgressCallback {
 public:
  explicit ProgressFunction(std::function<void(const ProgressEvent&)> f)
      : f_(std::move(f)) {}
  void operator()(const ProgressEvent& event) override { f_(event); }

 private:
  std::function<void(const ProgressEvent&)> f_;
};

// Calls `callback` with the event when it is not null.
inline void ReportProgress(ProgressCallback* callback,
                           const ProgressEvent& event) {
  if (callback != nullptr) (*callback)(event);
}

}  // namespace mlndt
