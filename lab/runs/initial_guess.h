#pragma once

// The initial-guess policies of a sequence run: where the initial
// reference_from_input of pair (i, j) comes from.

#include <string>

#include "mlndt/common/types.h"

namespace mlndt {

enum class InitMode {
  ZERO,         // Identity: no odometry (the paper's Z_i = 0).
  GT_FRACTION,  // c times the ground-truth motion (Z_i = c Z_gt, Table 9).
  CONSTANT_VELOCITY,  // The previous usable estimate (identity for the first).
  POSES,              // Relative motion from a KITTI pose file (odometry).
};

struct InitSpec {
  InitMode mode = InitMode::ZERO;
  double fraction = 1.0;   // GT_FRACTION: c.
  std::string poses_path;  // POSES: the file.
};

// Parses "zero", "gt_fraction:c", "constant_velocity" or "poses:FILE"; false
// with *error (naming the text as --init=...) for anything else.
bool ParseInitSpec(const std::string& text, InitSpec* spec, std::string* error);

// The text ParseInitSpec reads back ("gt_fraction:%g").
std::string InitSpecToString(const InitSpec& spec);

// The guesses of a run, pair by pair. For each pair call Guess, register,
// then Record the outcome (constant velocity reuses the last usable one).
class InitialGuessPolicy {
 public:
  explicit InitialGuessPolicy(const InitSpec& spec) : spec_(spec) {}

  // The guess for a pair whose ground-truth motion is `truth` (read only by
  // GT_FRACTION: ScaleMotion(truth, c)) and whose odometry motion is
  // `odometry` (read only by POSES).
  Isometry3d Guess(const Isometry3d& truth, const Isometry3d& odometry) const;

  // Records a pair's estimate; only a usable one becomes the next
  // CONSTANT_VELOCITY guess.
  void Record(bool usable, const Isometry3d& estimate);

 private:
  InitSpec spec_;
  Isometry3d previous_estimate_ = Isometry3d::Identity();
};

}  // namespace mlndt
