#pragma once

// The accuracy references of the shared data sets: reference_pairs.json
// (format in shared/data/README.md). Each entry, keyed "i_j" by the scan
// numbers in the file names (i = reference = target, j = input = source),
// holds the consensus of five third-party registrations of scan j onto scan
// i and how far the five spread around it, or, where the five disagreed
// (the Livox folders), the data set's prior, marked by a "source" member.
// Simulated sets (lab/sim) hold the exact pose ("source": "exact: ...",
// spreads 0) and the directions the scene leaves free.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "mlndt/common/types.h"

namespace mlndt {

struct ReferencePair {
  int64_t reference_index = 0;  // i.
  int64_t input_index = 0;      // j.
  // "reference_from_input": p_i = T p_j (12 numbers, row-major 3x4).
  Isometry3d reference_from_input = Isometry3d::Identity();
  // Largest distance of any of the five registrations from the consensus,
  // in translation [m] and rotation angle [deg]: each reference is good to
  // about this much.
  // Zero for a prior entry (its accuracy is not known from a spread).
  double spread_m = 0.0;
  double spread_deg = 0.0;
  // "source": empty for a consensus entry; for an entry that is not a
  // consensus, where the reference comes from (e.g. "prior: FAST-LIO2 ...").
  std::string source;
  // "prior_from_input", when present: the data set's own prior pose (the
  // registrations' start; KITTI: its official ground truth).
  std::optional<Isometry3d> prior_from_input;
  // "free_directions", when present: unit directions of the pose vector
  // (tx, ty, tz [m], alpha, beta, gamma [rad]; pose.h) of
  // reference_from_input, in the reference frame, along which the scene
  // does not constrain the pose (a corridor along x: [1,0,0,0,0,0]). Empty:
  // the scene constrains every direction (or the file does not say).
  std::vector<Vector6d> free_directions;
};

// "i_j".
std::string ReferencePairKey(int64_t reference_index, int64_t input_index);

// Reads the file into *pairs (cleared first), keyed as in the file. Other
// members of an entry ("methods", "medoid", ...) are ignored. Matrices are
// kept as written; a 3x3 part that is not a rotation within 1e-3 is an
// error. False with *error naming the file and, for a bad entry, its key
// and member, on malformed JSON, a key that is not "i_j" with non-negative
// integers, a missing member (the spreads may be missing only in an entry
// with a "source" string), an array that does not hold 12 finite numbers,
// a spread that is not a finite number >= 0, or "free_directions" that is
// not an array of arrays of 6 finite numbers, each of length 1 within
// 1e-6.
bool ReadReferencePairs(const std::string& path,
                        std::map<std::string, ReferencePair>* pairs,
                        std::string* error);

}  // namespace mlndt
