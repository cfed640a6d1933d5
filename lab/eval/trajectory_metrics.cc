#include "lab/eval/trajectory_metrics.h"

#include <glog/logging.h>

#include <cmath>
#include <utility>

#include "lab/eval/trajectory_evaluation_option_table.h"
#include "mlndt/common/pose.h"

namespace mlndt {
namespace {

bool CheckSizes(const char* metric,
                const std::vector<Isometry3d>& reference,
                const std::vector<Isometry3d>& estimate,
                std::string* error) {
  if (reference.size() != estimate.size()) {
    *error = std::string(metric) + ": " + std::to_string(reference.size()) +
             " reference poses but " + std::to_string(estimate.size()) +
             " estimated poses (associate them first)";
    return false;
  }
  return true;
}

// The alignment that maps estimated positions into the reference frame.
bool Align(TrajectoryAlignment alignment,
           const std::vector<Isometry3d>& reference,
           const std::vector<Isometry3d>& estimate,
           SimilarityTransform* reference_from_estimate,
           std::string* error) {
  *reference_from_estimate = SimilarityTransform();
  switch (alignment) {
    case TrajectoryAlignment::NONE:
      return true;
    case TrajectoryAlignment::FIRST_POSE: {
      const Isometry3d first = reference[0] * estimate[0].inverse();
      reference_from_estimate->rotation = first.linear();
      reference_from_estimate->translation = first.translation();
      return true;
    }
    case TrajectoryAlignment::SE3:
    case TrajectoryAlignment::SIM3: {
      std::vector<Vector3d> from, to;
      for (size_t k = 0; k < reference.size(); ++k) {
        from.push_back(estimate[k].translation());
        to.push_back(reference[k].translation());
      }
      if (UmeyamaAlignment(from,
                           to,
                           alignment == TrajectoryAlignment::SIM3,
                           reference_from_estimate,
                           error)) {
        return true;
      }
      *error = "ATE: " + *error;
      return false;
    }
  }
  *error = "ATE: unknown alignment";
  return false;
}

}  // namespace

const char* TrajectoryAlignmentToString(TrajectoryAlignment alignment) {
  return EnumToString(TrajectoryAlignmentTable(), alignment);
}

bool StringToTrajectoryAlignment(std::string value,
                                 TrajectoryAlignment* result) {
  return StringToEnum(TrajectoryAlignmentTable(), std::move(value), result);
}

bool ComputeAte(const AteOptions& options,
                const std::vector<Isometry3d>& reference,
                const std::vector<Isometry3d>& estimate,
                AteSummary* summary,
                std::string* error) {
  CHECK(summary != nullptr);
  CHECK(error != nullptr);
  *summary = AteSummary();
  if (!CheckSizes("ATE", reference, estimate, error)) return false;
  if (reference.empty()) {
    *error = "ATE: no poses";
    return false;
  }
  if (!Align(options.alignment,
             reference,
             estimate,
             &summary->reference_from_estimate,
             error)) {
    return false;
  }
  double sum_squares = 0.0;
  for (size_t k = 0; k < reference.size(); ++k) {
    const Vector3d difference =
        reference[k].translation() -
        summary->reference_from_estimate * estimate[k].translation();
    sum_squares += difference.squaredNorm();
    summary->errors_m.push_back(difference.norm());
  }
  summary->rmse_m =
      std::sqrt(sum_squares / static_cast<double>(reference.size()));
  summary->errors = ComputeStats(summary->errors_m);
  return true;
}

bool ComputeRpe(const RpeOptions& options,
                const std::vector<Isometry3d>& reference,
                const std::vector<Isometry3d>& estimate,
                RpeSummary* summary,
                std::string* error) {
  CHECK(summary != nullptr);
  CHECK(error != nullptr);
  *summary = RpeSummary();
  if (!CheckSizes("RPE", reference, estimate, error)) return false;
  if (options.delta < 1) {
    *error = "RPE: delta " + std::to_string(options.delta) + " < 1";
    return false;
  }
  const size_t delta = static_cast<size_t>(options.delta);
  if (reference.size() <= delta) {
    *error = "RPE: " + std::to_string(reference.size()) +
             " poses, more than delta = " + std::to_string(delta) + " needed";
    return false;
  }
  std::vector<double> translations, rotations;
  for (size_t k = 0; k + delta < reference.size(); ++k) {
    const Isometry3d q = reference[k].inverse() * reference[k + delta];
    const Isometry3d p = estimate[k].inverse() * estimate[k + delta];
    translations.push_back(TranslationErrorM(q, p));
    rotations.push_back(RotationErrorRad(q, p) * kRadToDeg);
  }
  summary->translation_m = ComputeStats(translations);
  summary->rotation_deg = ComputeStats(rotations);
  summary->translation_rmse_m = Rms(translations);
  summary->rotation_rmse_deg = Rms(rotations);
  return true;
}

}  // namespace mlndt
