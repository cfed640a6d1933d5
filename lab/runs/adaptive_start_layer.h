#pragma once

// The paper's adaptive start layer (end of Section 5.3). The paper proposes:
// start on the last layer (the odometry is assumed good); a registration
// counts as failed when the estimate differs from the odometry guess by more
// than 1 m or 15 deg; once the fail rate passes 5 % start on a coarser
// layer, and past 20 % on a coarser one still. Here, precisely:
//  * the guess is the initial guess of the pair (initial_guess.h, the
//    odometry stand-in);
//  * pair p (0-based) counts as failed when the registration reports
//    FAILURE, or TranslationErrorM(guess, estimate) > max_translation_m, or
//    RotationErrorRad(guess, estimate) > max_rotation_deg (CheckGuess);
//  * the running fail rate before pair p is failed(0..p-1) / p (0 for p = 0),
//    i.e. cumulative over every pair so far, so it rises with failures and
//    decays as successes accumulate;
//  * pair p starts k layers coarser than the last layer, where k is the
//    number of thresholds (default 5 % and 20 %) the running rate exceeds
//    strictly: schedule.start_layer = -k (layer_scheduler.h: 0 = last
//    layer, -1 = one coarser, ...), clamped to layer 1 by the scheduler.
// With a zero guess (no motion) any true motion above 1 m counts as a
// failure: the rule assumes an odometry-like guess.

#include <cstddef>
#include <string>
#include <vector>

#include "mlndt/common/types.h"

namespace mlndt {

struct AdaptiveStartLayerOptions {
  bool enabled = false;
  // A deviation of the estimate from the guess above this [m] is a failure.
  double max_translation_m = 1.0;
  // ... or above this rotation angle [deg].
  double max_rotation_deg = 15.0;
  // Ascending fail rates in [0, 1]: exceeding the k-th starts k layers
  // coarser than the last.
  std::vector<double> fail_rate_thresholds = {0.05, 0.20};

  // The ranges of AdaptiveStartLayerOptionsTable and ascending thresholds;
  // false with *error naming the field.
  bool IsValid(std::string* error) const;
};

// How far a pair's estimate ended from its guess, and the rule's verdict.
struct GuessCheck {
  double deviation_m = 0.0;
  double deviation_deg = 0.0;
  bool failed = false;  // Not usable, or beyond either limit.
};

GuessCheck CheckGuess(const AdaptiveStartLayerOptions& options,
                      bool usable,
                      const Isometry3d& guess,
                      const Isometry3d& estimate);

// The running fail rate over the pairs recorded so far and the start layer
// it gives the next pair.
class AdaptiveStartLayer {
 public:
  explicit AdaptiveStartLayer(const AdaptiveStartLayerOptions& options)
      : options_(options) {}

  // failed / recorded; 0 before the first pair.
  double running_fail_rate() const;
  // -k: k thresholds are exceeded strictly by running_fail_rate().
  int StartLayer() const;
  void Record(bool failed);

 private:
  AdaptiveStartLayerOptions options_;
  size_t recorded_ = 0;
  size_t failed_ = 0;
};

}  // namespace mlndt
