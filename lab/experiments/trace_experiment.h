#pragma once

// Figs. 10-13: the six parameters and the score against the iteration on
// one pair started from the reference pushed off (Section 5.1 pushes its
// Kvarntorp input off artificially), from RegistrationSummary::trace, for
// NDT and for ML-NDT with Newton and with LM under the paper preset and
// the defaults.

#include <string>
#include <vector>

#include "lab/experiments/datasets.h"
#include "mlndt/common/types.h"

namespace mlndt {
namespace experiments {

// One iteration of one method (iteration 0 is the start).
struct TracePoint {
  int iteration = 0;
  int layer = 0;
  double score = 0.0;
  double normalized_score = 0.0;  // score / max |score| of the method.
  Vector6d paper_error = Vector6d::Zero();  // PaperAxesError.
};

struct MethodTrace {
  std::string key;    // "ndt", "paper_newton", ...
  std::string label;  // "NDT", "ML-NDT Newton, paper preset", ...
  std::string termination;
  std::vector<TracePoint> points;
};

struct TraceExperiment {
  std::string dataset;
  std::string pair;
  std::string offset_label;  // The start's offset, e.g. "x+yaw=0.25,15".
  std::vector<MethodTrace> methods;
};

// Runs the traces on the first smallest-step pair of the first data set of
// 3dtk, kitti, mulran found; false with *error when a scan cannot be read
// or none of those is there.
bool RunTraceExperiment(const std::vector<ExperimentDataset>& datasets,
                        TraceExperiment* trace,
                        std::string* error);

// csv text of one method: iteration,layer,score,normalized_score,tx..gamma.
std::string TraceCsv(const MethodTrace& method);

}  // namespace experiments
}  // namespace mlndt
