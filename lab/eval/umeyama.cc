#include "lab/eval/umeyama.h"

#include <glog/logging.h>

#include <Eigen/SVD>

namespace mlndt {

bool UmeyamaAlignment(const std::vector<Vector3d>& source,
                      const std::vector<Vector3d>& target,
                      bool with_scale,
                      SimilarityTransform* target_from_source,
                      std::string* error) {
  CHECK(target_from_source != nullptr);
  CHECK(error != nullptr);
  if (source.size() != target.size()) {
    *error = "Umeyama alignment: " + std::to_string(source.size()) +
             " source points but " + std::to_string(target.size()) +
             " target points";
    return false;
  }
  const size_t n = source.size();
  if (n < 3) {
    *error = "Umeyama alignment: " + std::to_string(n) +
             " point pairs, at least 3 needed";
    return false;
  }
  // Means (Eqs. 34, 35).
  Vector3d mean_source = Vector3d::Zero(), mean_target = Vector3d::Zero();
  for (size_t i = 0; i < n; ++i) {
    mean_source += source[i];
    mean_target += target[i];
  }
  mean_source /= static_cast<double>(n);
  mean_target /= static_cast<double>(n);
  // Variance of the source (Eq. 36) and the cross-covariance (Eq. 38).
  double variance_source = 0.0;
  Matrix3d covariance = Matrix3d::Zero();
  for (size_t i = 0; i < n; ++i) {
    const Vector3d x = source[i] - mean_source;
    variance_source += x.squaredNorm();
    covariance += (target[i] - mean_target) * x.transpose();
  }
  variance_source /= static_cast<double>(n);
  covariance /= static_cast<double>(n);
  if (!(variance_source > 0.0)) {
    *error = "Umeyama alignment: the source points all coincide";
    return false;
  }
  // R = U S V^T with S = diag(1, 1, -1) when det(U) det(V) < 0, so that R
  // is a rotation and not a reflection (Eqs. 39, 40, 43).
  const Eigen::JacobiSVD<Matrix3d> svd(
      covariance, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Vector3d s = Vector3d::Ones();
  if (svd.matrixU().determinant() * svd.matrixV().determinant() < 0.0) {
    s(2) = -1.0;
  }
  target_from_source->rotation =
      svd.matrixU() * s.asDiagonal() * svd.matrixV().transpose();
  // c = tr(D S) / sigma_x^2 (Eq. 42); t = mu_y - c R mu_x (Eq. 41).
  target_from_source->scale =
      with_scale ? svd.singularValues().dot(s) / variance_source : 1.0;
  target_from_source->translation =
      mean_target -
      target_from_source->scale * (target_from_source->rotation * mean_source);
  return true;
}

}  // namespace mlndt
