#pragma once

// The run plan of a registration suite (issue 12): over data set folders
// that hold a reference_pairs.json (reference_pairs.h), which scan pairs
// are registered from which starts. The runs are executed by
// pipeline/suite_runner.h and scored by eval/suite_score.h.
//
// A start is an initial reference_from_input:
//   identity           the identity;
//   prior              the pair's prior_from_input (pairs without one are
//                      skipped);
//   offsets            offset ∘ reference for each StartOffset: the
//                      reference pushed off in the reference frame;
//   perturbed          offset ∘ reference for a seeded random offset of at
//                      most (translation_m, rotation_deg), registered with
//                      that bound as the initial uncertainty;
//   constant_velocity  for pair i -> i+s the reference of (i-s) -> i (the
//                      motion of the previous s scans; pairs without it are
//                      skipped).

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "lab/eval/pose_error.h"
#include "lab/eval/reference_pairs.h"
#include "mlndt/common/types.h"

namespace mlndt {

// ---- Data sets and their scans ---------------------------------------------

// One data set of a suite.
struct SuiteDataset {
  std::string name;  // For reports (e.g. the folder's name).
  std::string dir;   // Holds reference_pairs.json; the scans are in it or pcd/.
  SuccessCriterion criterion;  // A run is right when within it.
};

// The number a scan file stands for: the digits of its file name without
// the extension, taken together ("000007.pcd" -> 7, "scan001.3d" -> 1,
// "room_scan1.pcd" -> 1, "251370668.pcd" -> 251370668). False when the
// name has no digit or more than 18.
bool ScanNumberFromFileName(const std::string& path, int64_t* number);

// The cloud files (ListScanFiles, dataset.h) of a data set folder's pcd/
// subfolder and of the folder itself, each sorted by name; either may be
// empty, not both.
struct DatasetScanFiles {
  std::vector<std::string> pcd_folder;
  std::vector<std::string> folder;
};

// False with *error when `dir` is not a folder or neither it nor dir/pcd
// holds a cloud file.
bool ListDatasetScanFiles(const std::string& dir,
                          DatasetScanFiles* files,
                          std::string* error);

// The file of scan `number`: the one file of pcd/ whose number it is, else
// the one file of the folder (so pose files such as poses_cam0.txt beside a
// pcd/ folder are never taken for scan 0). False with *error naming the
// number when no file has it, or naming the files when two in the same
// folder have it.
bool FindScanFile(const DatasetScanFiles& files,
                  int64_t number,
                  std::string* path,
                  std::string* error);

// ---- Starts ---------------------------------------------------------------

enum class StartKind {
  IDENTITY,
  PRIOR,
  OFFSETS,
  PERTURBED,
  CONSTANT_VELOCITY,
};

// "identity", "prior", "offsets", "perturbed", "constant_velocity" (the
// names the tools' --starts flag takes).
const char* StartKindToString(StartKind kind);
// Case-insensitive.
bool StringToStartKind(std::string value, StartKind* kind);

// One offset of the reference, applied as offset ∘ reference: translation
// [m] along the reference frame's x, y, z and rotation about its x, y, z
// (roll, pitch, yaw; R = Rx Ry Rz, Eq. 7) about its origin.
struct StartOffset {
  std::string family;  // Its axes as written, e.g. "x", "yaw", "xyyaw".
  std::string label;   // family=values, e.g. "x=2", "xyyaw=3,3,20".
  Vector6d reference_xi = Vector6d::Zero();  // (t [m], angles [rad]).
};

// Parses ';'-separated families "AXES:v1,v2,...". AXES names one or more
// of x, y, z [m] and roll, pitch, yaw [deg], written together ("xyyaw") or
// joined by '+' ("x+y+yaw"), each at most once. With one axis every value
// is one offset; with k axes the values are taken k at a time, one offset
// per group ("xyyaw:3,3,20" is one offset of 3 m, 3 m and 20°). Within a
// family list the offsets in growing size: the reach (suite_score.h)
// reads them in order. False with *error naming the bad item.
bool ParseStartOffsets(const std::string& text,
                       std::vector<StartOffset>* offsets,
                       std::string* error);

// How far a start may be from the truth, when it is known (passed to the
// registration as its initial uncertainty).
struct StartUncertainty {
  bool given = false;
  double translation_m = 0.0;
  double rotation_deg = 0.0;
};

// A random offset of at most `max_translation_m` in a uniformly random
// direction (length uniform in [0, max]) and at most `max_rotation_deg`
// about a uniformly random axis (angle uniform in [0, max]), drawn from a
// generator seeded by (seed, text): the same for the same pair and index
// whatever else the suite runs.
Isometry3d RandomStartOffset(double max_translation_m,
                             double max_rotation_deg,
                             uint64_t seed,
                             const std::string& text);

// ---- The plan -------------------------------------------------------------

struct SuitePlanOptions {
  // Start kinds run for every pair, in this order.
  std::vector<StartKind> starts = {StartKind::IDENTITY};
  std::vector<StartOffset> offsets;  // OFFSETS.
  // PERTURBED: the bound of the random offsets and how many per pair.
  double perturb_translation_m = 0.5;
  double perturb_rotation_deg = 5.0;
  int perturb_count = 1;
  uint64_t perturb_seed = 1;
  // PRIOR: the prior's uncertainty, when known.
  StartUncertainty prior_uncertainty;
  // Pairs i -> j kept by j - i; empty keeps all. Applies to data sets with
  // more than one pair (a single pair is always kept).
  std::vector<int64_t> steps;
  // At most this many pairs per data set (0: all): the smallest steps
  // first, then the smallest reference index.
  size_t max_pairs_per_set = 0;

  // The ranges of SuitePlanOptionsTable, then the starts (none twice,
  // offsets given for OFFSETS), the prior's uncertainty and the steps (not
  // 0); false with *error.
  bool IsValid(std::string* error) const;
};

// One registration of the plan.
struct SuiteRun {
  size_t dataset = 0;    // Index of the data set in the suite.
  std::string pair_key;  // "i_j".
  int64_t reference_index = 0;
  int64_t input_index = 0;
  StartKind kind = StartKind::IDENTITY;
  // The start's name: "identity", "prior", the offset's label, "perturbed#k",
  // "constant_velocity".
  std::string start;
  int offset_index = -1;  // OFFSETS: index into SuitePlanOptions::offsets.
  Isometry3d reference_from_input = Isometry3d::Identity();  // The truth.
  Isometry3d initial_reference_from_input = Isometry3d::Identity();
  StartUncertainty uncertainty;
  // The pair's free directions (ReferencePair::free_directions): the
  // scene leaves the pose free along them (suite_score.h scores such a
  // run by its verdict).
  std::vector<Vector6d> free_directions;
};

// Per start kind, the pairs it did not apply to (no prior, no previous
// pair).
using SuiteSkips = std::map<StartKind, size_t>;

// The runs of one data set in run order: pairs by reference index, then
// input index (so each reference map serves its pairs in a row), and per
// pair the starts in the order of options.starts (offsets in their order,
// perturbed 0 .. count-1). `dataset_name` seeds the perturbations. Every
// start is made rigid (its rotation replaced by the nearest rotation): the
// files' 6-9 significant digits leave |R^T R - I| near 1e-6, which the
// registration refuses in an initial guess.
std::vector<SuiteRun> PlanDatasetRuns(
    const SuitePlanOptions& options,
    size_t dataset,
    const std::string& dataset_name,
    const std::map<std::string, ReferencePair>& pairs,
    SuiteSkips* skips);

// A data set ready to run (lab/programs/suite_inputs.h LoadSuiteDataset
// reads one).
struct LoadedSuiteDataset {
  SuiteDataset dataset;
  std::map<std::string, ReferencePair> pairs;  // reference_pairs.json.
  std::vector<SuiteRun> runs;                  // PlanDatasetRuns.
  SuiteSkips skips;
  std::map<int64_t, std::string> scan_paths;  // Every scan the runs read.
};

}  // namespace mlndt
