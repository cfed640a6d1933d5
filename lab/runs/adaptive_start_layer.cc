#include "lab/runs/adaptive_start_layer.h"

#include <algorithm>

#include "lab/runs/adaptive_start_layer_option_table.h"
#include "mlndt/common/pose.h"

namespace mlndt {

bool AdaptiveStartLayerOptions::IsValid(std::string* error) const {
  if (!AdaptiveStartLayerOptionsTable().Check(*this, error)) return false;
  if (!std::is_sorted(fail_rate_thresholds.begin(),
                      fail_rate_thresholds.end())) {
    *error = "invalid option: fail_rate_thresholds must be ascending";
    return false;
  }
  return true;
}

GuessCheck CheckGuess(const AdaptiveStartLayerOptions& options,
                      bool usable,
                      const Isometry3d& guess,
                      const Isometry3d& estimate) {
  GuessCheck check;
  check.deviation_m = TranslationErrorM(guess, estimate);
  check.deviation_deg = RotationErrorRad(guess, estimate) * kRadToDeg;
  check.failed = !usable || check.deviation_m > options.max_translation_m ||
                 check.deviation_deg > options.max_rotation_deg;
  return check;
}

double AdaptiveStartLayer::running_fail_rate() const {
  return recorded_ == 0 ? 0.0 : double(failed_) / recorded_;
}

int AdaptiveStartLayer::StartLayer() const {
  const double rate = running_fail_rate();
  int coarser = 0;
  for (double threshold : options_.fail_rate_thresholds) {
    if (rate > threshold) ++coarser;
  }
  return -coarser;
}

void AdaptiveStartLayer::Record(bool failed) {
  ++recorded_;
  failed_ += failed;
}

}  // namespace mlndt
