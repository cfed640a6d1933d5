#include "lab/experiments/trace_experiment.h"

#include <algorithm>
#include <cmath>

#include "lab/experiments/configurations.h"
#include "lab/experiments/paper_axes.h"
#include "lab/experiments/run_batch.h"
#include "lab/report/text_format.h"
#include "lab/runs/matcher.h"
#include "mlndt/cloud/io.h"
#include "mlndt/common/pose.h"
#include "mlndt/solvers/levenberg_marquardt_backend.h"

namespace mlndt {
namespace experiments {
namespace {

// The paper's claimed ML-NDT reach (Section 5.1), 25 cm and 15 deg.
constexpr char kTraceOffset[] = "x+yaw:0.25,15";

Configuration WithBackend(Configuration c,
                          BackendType type,
                          const std::string& key,
                          const std::string& label) {
  c.options.mlndt.backend.type = type;
  c.key = key;
  c.label = label;
  return c;
}

// The paper's literal LM (scalar residual s_k, Eqs. 18-20).
Configuration PaperScalarLm(const Configuration& paper) {
  Configuration c = WithBackend(paper,
                                BackendType::LEVENBERG_MARQUARDT,
                                "paper_lm_scalar",
                                "ML-NDT LM with scalar s_k, paper preset");
  c.options.mlndt.backend.levenberg_marquardt.residual =
      LmResidual::SCALAR_SCORE;
  return c;
}

// The trace of one registration: its start and every iteration, as errors
// in the paper's axes and scores normalised by the largest |score|.
MethodTrace MakeMethodTrace(const Configuration& c,
                            const SuiteRun& run,
                            const RegistrationSummary& summary) {
  MethodTrace method;
  method.key = c.key;
  method.label = c.label;
  method.termination = TerminationTypeToString(summary.termination_type);
  TracePoint start;
  start.score = summary.initial_score;
  start.layer = summary.start_layer;
  start.paper_error = PaperAxesError(run.reference_from_input,
                                     run.initial_reference_from_input);
  method.points.push_back(start);
  for (const IterationRecord& r : summary.trace) {
    TracePoint p;
    p.iteration = r.iteration;
    p.layer = r.layer;
    p.score = r.score;
    p.paper_error =
        PaperAxesError(run.reference_from_input,
                       PoseVectorToIsometry(r.reference_from_input_xi));
    method.points.push_back(p);
  }
  double max_abs = 0.0;
  for (const TracePoint& p : method.points)
    max_abs = std::max(max_abs, std::abs(p.score));
  for (TracePoint& p : method.points)
    p.normalized_score = max_abs > 0.0 ? p.score / max_abs : 0.0;
  return method;
}

}  // namespace

bool RunTraceExperiment(const std::vector<ExperimentDataset>& datasets,
                        TraceExperiment* trace,
                        std::string* error) {
  const ExperimentDataset* set = nullptr;
  size_t index = 0;
  for (const char* name : {"3dtk", "kitti", "mulran"}) {
    for (size_t d = 0; d < datasets.size() && !set; ++d) {
      if (datasets[d].name == name) {
        set = &datasets[d];
        index = d;
      }
    }
  }
  if (!set || set->pairs.empty()) {
    *error = "no 3dtk, kitti or mulran data set for Figs. 10-13";
    return false;
  }
  std::vector<StartOffset> offsets;
  if (!ParseStartOffsets(kTraceOffset, &offsets, error)) return false;
  const std::string pair = set->PairsByStep().front();
  const SuiteRun run = OffsetStart(index, *set, pair, offsets[0], 0);
  trace->dataset = set->name;
  trace->pair = pair;
  trace->offset_label = offsets[0].label;
  trace->methods.clear();

  PointCloud reference, input;
  if (!ReadPointCloud(set->scan_paths.at(run.reference_index),
                      &reference,
                      nullptr,
                      error) ||
      !ReadPointCloud(
          set->scan_paths.at(run.input_index), &input, nullptr, error)) {
    return false;
  }
  const Configuration paper = PaperConfiguration();
  const Configuration defaults = DefaultConfiguration();
  const std::vector<Configuration> methods = {
      NdtConfiguration(),
      WithBackend(paper,
                  BackendType::NEWTON,
                  "paper_newton",
                  "ML-NDT Newton, paper preset"),
      WithBackend(paper,
                  BackendType::LEVENBERG_MARQUARDT,
                  "paper_lm",
                  "ML-NDT LM, paper preset"),
      PaperScalarLm(paper),
      WithBackend(defaults,
                  BackendType::NEWTON,
                  "defaults_newton",
                  "ML-NDT Newton, defaults"),
      WithBackend(defaults,
                  BackendType::LEVENBERG_MARQUARDT,
                  "defaults_lm",
                  "ML-NDT LM, defaults"),
  };
  for (const Configuration& c : methods) {
    RegistrationSummary summary;
    RegisterWithMatcher(c.options,
                        reference,
                        input,
                        run.initial_reference_from_input,
                        &summary);
    trace->methods.push_back(MakeMethodTrace(c, run, summary));
  }
  return true;
}

std::string TraceCsv(const MethodTrace& method) {
  std::string csv =
      "iteration,layer,score,normalized_score,tx_cm,ty_cm,tz_cm,alpha_deg,"
      "beta_deg,gamma_deg\n";
  for (const TracePoint& p : method.points) {
    csv += std::to_string(p.iteration) + "," + std::to_string(p.layer) + "," +
           Num(p.score) + "," + Num(p.normalized_score);
    for (int i = 0; i < 6; ++i) csv += "," + Num(p.paper_error(i));
    csv += "\n";
  }
  return csv;
}

}  // namespace experiments
}  // namespace mlndt
