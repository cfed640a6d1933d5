#include "mlndt/solvers/backend.h"

#include <glog/logging.h>

#include "mlndt/common/enum_strings.h"

namespace mlndt {

const char* BackendTypeToString(BackendType type) {
  switch (type) {
    case BackendType::CERES:
      return "CERES";
    case BackendType::NEWTON:
      return "NEWTON";
    case BackendType::LEVENBERG_MARQUARDT:
      return "LEVENBERG_MARQUARDT";
  }
  return "UNKNOWN";
}

ScoreOptions ScoreOptionsForStage(const StageOptions& options) {
  ScoreOptions score;
  score.unmatched_policy = options.unmatched_policy;
  score.loss = options.loss;
  score.loss_scale = options.loss_scale;
  score.num_threads = options.num_threads;
  return score;
}

namespace internal {

const std::vector<Eigen::Vector3d>& EveryNthPoint(
    const std::vector<Eigen::Vector3d>& points,
    int stride,
    std::vector<Eigen::Vector3d>* storage) {
  CHECK_GE(stride, 1);
  if (stride == 1) return points;
  storage->clear();
  storage->reserve(points.size() / static_cast<size_t>(stride) + 1);
  for (size_t i = 0; i < points.size(); i += static_cast<size_t>(stride)) {
    storage->push_back(points[i]);
  }
  return *storage;
}

}  // namespace internal

bool StringToBackendType(std::string value, BackendType* result) {
  UpperCase(&value);
  if (value == "LM") value = "LEVENBERG_MARQUARDT";
  MLNDT_STRING_TO_ENUM(CERES, BackendType);
  MLNDT_STRING_TO_ENUM(NEWTON, BackendType);
  MLNDT_STRING_TO_ENUM(LEVENBERG_MARQUARDT, BackendType);
  return false;
}

}  // namespace mlndt
