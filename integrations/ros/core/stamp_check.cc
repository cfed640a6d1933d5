#include "integrations/ros/core/stamp_check.h"

#include <cstdio>

namespace mlndt {
namespace ros_core {
namespace {

std::string Seconds(double s) {
  char text[64];
  std::snprintf(text, sizeof(text), "%.6f s", s);
  return text;
}

}  // namespace

bool StampCheck::Check(double stamp_s,
                       std::string* refusal,
                       std::string* gap_note) const {
  gap_note->clear();
  if (!has_last_) return true;
  if (!(stamp_s > last_s_)) {
    *refusal = "stamp " + Seconds(stamp_s) + " is not after the last scan's (" +
               Seconds(last_s_) + "): a repeated or reordered message";
    return false;
  }
  const double interval = stamp_s - last_s_;
  if (regular_interval_s_ > 0.0 &&
      interval > kGapFactor * regular_interval_s_) {
    *gap_note = "gap of " + Seconds(interval) + " since the last scan (" +
                Seconds(regular_interval_s_) +
                " before): messages dropped? The prediction bridges it";
  }
  return true;
}

void StampCheck::Use(double stamp_s) {
  if (has_last_) {
    const double interval = stamp_s - last_s_;
    if (regular_interval_s_ == 0.0 ||
        interval <= kGapFactor * regular_interval_s_) {
      regular_interval_s_ = interval;
    }
  }
  has_last_ = true;
  last_s_ = stamp_s;
}

void StampCheck::Reset() { *this = StampCheck(); }

}  // namespace ros_core
}  // namespace mlndt
