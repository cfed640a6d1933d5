#pragma once

// mlndt_suite's inputs: the --datasets list and the data sets it names,
// each with its reference pairs, its planned runs and the files of the
// scans those runs read, all checked before any registration runs.

#include <map>
#include <string>
#include <vector>

#include "lab/eval/reference_pairs.h"
#include "lab/eval/suite_plan.h"

namespace mlndt {
namespace lab {

// Parses "DIR[:tol_m:tol_deg],..." (the default tolerance is
// SuccessCriterion's). A relative DIR is taken inside `data_dir` when that
// is not empty (a `data_dir` that is not a folder is refused). The data
// set's name is the folder's name (the last part of DIR); two with the same
// name are refused. False with *error naming the item (and the flag).
bool ParseSuiteDatasets(const std::string& text,
                        const std::string& data_dir,
                        std::vector<SuiteDataset>* datasets,
                        std::string* error);

// `plan` runs the start `kind`.
bool HasStart(const SuitePlanOptions& plan, StartKind kind);

// Flags that only apply with a start kind, refused without it; and
// --initial_uncertainty, refused where the start's own (the perturbed
// bound, `prior_uncertainty` = --prior_uncertainty) would override it.
bool RefuseUnusedStartFlags(const SuitePlanOptions& plan,
                            const std::string& prior_uncertainty,
                            std::string* error);

// A "translation_m,rotation_deg" pair flag --<flag>=`text`.
bool ParseBound(const char* flag,
                const std::string& text,
                double* translation_m,
                double* rotation_deg,
                std::string* error);

// LoadSuiteDataset (lab/runs/suite_run.h) of every data set, in order;
// *error names the data set (--datasets 'NAME': ...).
bool LoadSuiteDatasets(const std::vector<SuiteDataset>& datasets,
                       const SuitePlanOptions& plan,
                       std::vector<LoadedSuiteDataset>* loaded,
                       std::string* error);

// The plan's numbers set by text flags in range: the perturbed and prior
// bounds within [0, 1e4] m and [0, 180] deg, no step 0; *error names the
// flag. (The table flags' ranges are checked as they are applied.)
bool CheckSuitePlanBounds(const SuitePlanOptions& plan, std::string* error);

// --reach_share in (0, 1]; --plot needs --output_dir and a gnuplot that
// runs; --gnuplot needs --plot.
bool CheckSuiteOutputFlags(double reach_share,
                           bool plot,
                           const std::string& output_dir,
                           const std::string& gnuplot,
                           std::string* error);

// --starts=`text`: "identity,prior,..." into start kinds.
bool ParseStartList(const std::string& text,
                    std::vector<StartKind>* starts,
                    std::string* error);

}  // namespace lab
}  // namespace mlndt
