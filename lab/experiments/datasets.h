#pragma once

// The data sets of the report: the shared folders with a
// reference_pairs.json (shared/data/README.md) or the repository's bundled
// subsets of them (data/), found by name under one folder.

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "lab/eval/pose_error.h"
#include "lab/eval/reference_pairs.h"
#include "lab/eval/suite_plan.h"

namespace mlndt {
namespace experiments {

struct ExperimentDataset {
  std::string name;            // "kitti", "mulran", "3dtk", "room", "koide3".
  std::string dir;             // The folder found.
  SuccessCriterion criterion;  // The strict rule for this data set.
  std::map<std::string, ReferencePair> pairs;  // reference_pairs.json.
  std::map<int64_t, std::string> scan_paths;   // Every scan of the pairs.

  // Pairs "i_j" with j - i == step, in reference order.
  std::vector<std::string> PairsWithStep(int64_t step) const;
  // Every pair, by step and then reference index.
  std::vector<std::string> PairsByStep() const;
};

// Finds every named data set under `data_dir` (shared names such as
// kitti00_frames_0000_0007 first, then the bundled kitti, room, koide3),
// reads its references and finds its scans. Missing data sets are listed
// in *missing; false with *error when a folder is found but unreadable.
bool FindDatasets(const std::string& data_dir,
                  std::vector<ExperimentDataset>* datasets,
                  std::vector<std::string>* missing,
                  std::string* error);

}  // namespace experiments
}  // namespace mlndt
