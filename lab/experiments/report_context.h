#pragma once

// What every section of the report reads: the data sets, the records of
// every run, the plan, and the files the sections add.

#include <string>
#include <vector>

#include "lab/experiments/datasets.h"
#include "lab/experiments/experiment_plan.h"
#include "lab/experiments/report_files.h"
#include "lab/experiments/run_batch.h"

namespace mlndt {
namespace experiments {

struct ReportContext {
  const std::vector<ExperimentDataset>* datasets = nullptr;
  const std::vector<RunRecord>* records = nullptr;
  ExperimentPlan plan;
  ReportFiles* files = nullptr;  // Not owned.
};

// Records of `experiment` ("" = any), data set ("" = any) and config key
// ("" = any), in run order.
std::vector<const RunRecord*> Select(const ReportContext& c,
                                     const std::string& experiment,
                                     const std::string& dataset,
                                     const std::string& config);

// "85.7 %" (one decimal), "–" without runs.
std::string Percent(size_t part, size_t whole);
double PercentValue(size_t part, size_t whole);  // NaN without runs.

// The data set of Figs. 14-18 (the paper's scan sequence): the one with
// the most smallest-step pairs in the accuracy runs; "" when none ran.
std::string SequenceDataset(const ReportContext& c);

// Its smallest-step pairs in reference order.
std::vector<std::string> SequencePairs(const ReportContext& c);

const ExperimentDataset* FindDataset(const ReportContext& c,
                                     const std::string& name);

}  // namespace experiments
}  // namespace mlndt
