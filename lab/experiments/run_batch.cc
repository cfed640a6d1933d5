#include "lab/experiments/run_batch.h"

#include <sstream>

#include "lab/experiments/paper_axes.h"
#include "lab/report/chained_progress.h"
#include "lab/report/text_format.h"
#include "lab/runs/suite_runner.h"
#include "mlndt/common/pose.h"

namespace mlndt {
namespace experiments {
namespace {

// The nearest rotation: the files' 6-9 significant digits leave R^T R - I
// near 1e-6, which the registration refuses in a guess.
Isometry3d Rigid(const Isometry3d& t) {
  Isometry3d out = Isometry3d::Identity();
  out.linear() = Eigen::Quaterniond(t.linear()).normalized().toRotationMatrix();
  out.translation() = t.translation();
  return out;
}

SuiteRun BaseRun(size_t dataset,
                 const ExperimentDataset& set,
                 const std::string& pair) {
  const ReferencePair& p = set.pairs.at(pair);
  SuiteRun run;
  run.dataset = dataset;
  run.pair_key = pair;
  run.reference_index = p.reference_index;
  run.input_index = p.input_index;
  run.reference_from_input = p.reference_from_input;
  return run;
}

// The record of one run of `job` on `set`.
RunRecord MakeRecord(const Job& job,
                     const ExperimentDataset& set,
                     const SuiteRun& run,
                     const SuiteRunResult& r) {
  RunRecord record;
  record.experiment = job.experiment;
  record.dataset = set.name;
  record.config = job.config.key;
  record.pair = run.pair_key;
  record.start = run.start;
  record.offset_index = run.offset_index;
  record.parameter = job.parameter;
  record.termination = r.outcome.termination;
  record.right = r.outcome.right;
  record.translation_m = r.outcome.error.translation_m;
  record.rotation_deg = r.outcome.error.rotation_deg();
  record.paper_right = record.translation_m < kPaperSuccessTranslationM;
  record.diverged =
      !(record.translation_m <= 1.0) || !(record.rotation_deg <= 15.0);
  record.paper_error = PaperAxesError(run.reference_from_input,
                                      r.registration.reference_from_input);
  record.time_ms = r.outcome.time_ms;
  record.iterations = r.registration.num_iterations;
  return record;
}

}  // namespace

SuiteRun IdentityStart(size_t dataset,
                       const ExperimentDataset& set,
                       const std::string& pair) {
  SuiteRun run = BaseRun(dataset, set, pair);
  run.kind = StartKind::IDENTITY;
  run.start = "identity";
  return run;
}

SuiteRun PriorStart(size_t dataset,
                    const ExperimentDataset& set,
                    const std::string& pair) {
  SuiteRun run = BaseRun(dataset, set, pair);
  run.kind = StartKind::PRIOR;
  run.start = "prior";
  const ReferencePair& p = set.pairs.at(pair);
  run.initial_reference_from_input =
      Rigid(p.prior_from_input.value_or(Isometry3d::Identity()));
  return run;
}

SuiteRun OffsetStart(size_t dataset,
                     const ExperimentDataset& set,
                     const std::string& pair,
                     const StartOffset& offset,
                     int offset_index) {
  SuiteRun run = BaseRun(dataset, set, pair);
  run.kind = StartKind::OFFSETS;
  run.start = offset.label;
  run.offset_index = offset_index;
  run.initial_reference_from_input = Rigid(
      PoseVectorToIsometry(offset.reference_xi) * run.reference_from_input);
  return run;
}

SuiteRun ScaledStart(size_t dataset,
                     const ExperimentDataset& set,
                     const std::string& pair,
                     double c) {
  SuiteRun run = BaseRun(dataset, set, pair);
  run.kind = StartKind::IDENTITY;
  std::ostringstream label;
  label << "c=" << c;
  run.start = label.str();
  run.initial_reference_from_input = Rigid(
      PoseVectorToIsometry(c * IsometryToPoseVector(run.reference_from_input)));
  return run;
}

bool RunJobs(const std::vector<ExperimentDataset>& datasets,
             const std::vector<Job>& jobs,
             ProgressCallback* progress,
             std::vector<RunRecord>* records,
             std::string* error) {
  size_t total = 0;
  for (const Job& job : jobs) total += job.runs.size();
  ChainedProgress chained(progress, total);
  for (const Job& job : jobs) {
    const ExperimentDataset& set = datasets.at(job.dataset);
    chained.Next(job.experiment + " " + set.name + " " + job.config.key);
    std::vector<SuiteRunResult> results;
    if (!RunSuiteDataset(job.config.options,
                         set.criterion,
                         set.scan_paths,
                         job.runs,
                         &chained,
                         &results,
                         error)) {
      *error = set.name + ": " + *error;
      return false;
    }
    for (size_t k = 0; k < results.size(); ++k) {
      records->push_back(MakeRecord(job, set, job.runs[k], results[k]));
    }
  }
  return true;
}

std::string RunRecordsCsv(const std::vector<RunRecord>& records) {
  std::string csv =
      "experiment,dataset,config,pair,start,offset_index,parameter,"
      "termination,right,paper_right,diverged,tx_cm,ty_cm,tz_cm,alpha_deg,"
      "beta_deg,gamma_deg,translation_m,rotation_deg,time_ms,iterations\n";
  for (const RunRecord& r : records) {
    csv += CsvField(r.experiment) + "," + CsvField(r.dataset) + "," +
           CsvField(r.config) + "," + CsvField(r.pair) + "," +
           CsvField(r.start) + "," + std::to_string(r.offset_index) + "," +
           Num(r.parameter) + "," + TerminationTypeToString(r.termination) +
           "," + (r.right ? "1" : "0") + "," + (r.paper_right ? "1" : "0") +
           "," + (r.diverged ? "1" : "0");
    for (int i = 0; i < 6; ++i) csv += "," + Num(r.paper_error(i));
    csv += "," + Num(r.translation_m) + "," + Num(r.rotation_deg) + "," +
           Num(r.time_ms) + "," + std::to_string(r.iterations) + "\n";
  }
  return csv;
}

}  // namespace experiments
}  // namespace mlndt
