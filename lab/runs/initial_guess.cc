#include "lab/runs/initial_guess.h"

#include <cmath>
#include <cstdio>

#include "lab/eval/pose_error.h"

namespace mlndt {
namespace {

// One finite number, surrounding blanks allowed.
bool ParseOneNumber(const std::string& text, double* value) {
  try {
    size_t used = 0;
    *value = std::stod(text, &used);
    return text.find_first_not_of(" \t", used) == std::string::npos &&
           std::isfinite(*value);
  } catch (...) {
    return false;
  }
}

}  // namespace

bool ParseInitSpec(const std::string& text,
                   InitSpec* spec,
                   std::string* error) {
  *spec = InitSpec();
  if (text == "zero") return true;
  if (text == "constant_velocity") {
    spec->mode = InitMode::CONSTANT_VELOCITY;
    return true;
  }
  const std::string fraction_prefix = "gt_fraction:";
  if (text.rfind(fraction_prefix, 0) == 0) {
    if (!ParseOneNumber(text.substr(fraction_prefix.size()), &spec->fraction)) {
      *error = "--init=" + text +
               ": gt_fraction needs one number, e.g. gt_fraction:0.6";
      return false;
    }
    spec->mode = InitMode::GT_FRACTION;
    return true;
  }
  const std::string poses_prefix = "poses:";
  if (text.rfind(poses_prefix, 0) == 0 && text.size() > poses_prefix.size()) {
    spec->mode = InitMode::POSES;
    spec->poses_path = text.substr(poses_prefix.size());
    return true;
  }
  *error = "--init=" + text +
           ": expected zero, gt_fraction:c, constant_velocity or poses:FILE";
  return false;
}

std::string InitSpecToString(const InitSpec& spec) {
  switch (spec.mode) {
    case InitMode::ZERO:
      return "zero";
    case InitMode::GT_FRACTION: {
      char text[64];
      std::snprintf(text, sizeof(text), "gt_fraction:%g", spec.fraction);
      return text;
    }
    case InitMode::CONSTANT_VELOCITY:
      return "constant_velocity";
    case InitMode::POSES:
      return "poses:" + spec.poses_path;
  }
  return "?";
}

Isometry3d InitialGuessPolicy::Guess(const Isometry3d& truth,
                                     const Isometry3d& odometry) const {
  switch (spec_.mode) {
    case InitMode::ZERO:
      return Isometry3d::Identity();
    case InitMode::GT_FRACTION:
      return ScaleMotion(truth, spec_.fraction);
    case InitMode::CONSTANT_VELOCITY:
      return previous_estimate_;
    case InitMode::POSES:
      return odometry;
  }
  return Isometry3d::Identity();
}

void InitialGuessPolicy::Record(bool usable, const Isometry3d& estimate) {
  if (usable) previous_estimate_ = estimate;
}

}  // namespace mlndt
