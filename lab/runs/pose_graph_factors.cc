#include "lab/runs/pose_graph_factors.h"

#include <ceres/autodiff_cost_function.h>
#include <ceres/manifold.h>
#include <ceres/rotation.h>

#include <Eigen/Geometry>
#include <cmath>

namespace mlndt {
namespace {

struct OdometryFactor {
  OdometryFactor(const Isometry3d& measured, const OdometryNoise& noise)
      : rotation(measured.linear()),
        translation(measured.translation()),
        inv_sigma_m(1.0 / noise.sigma_m),
        inv_sigma_rad(180.0 / (M_PI * noise.sigma_deg)) {}

  template <typename T>
  bool operator()(const T* q_i,
                  const T* t_i,
                  const T* q_j,
                  const T* t_j,
                  T* residual) const {
    using Quaternion = Eigen::Quaternion<T>;
    using Vector = Eigen::Matrix<T, 3, 1>;
    const Eigen::Map<const Quaternion> rotation_i(q_i), rotation_j(q_j);
    const Eigen::Map<const Vector> translation_i(t_i), translation_j(t_j);
    // T_i^-1 T_j, then the error against the measurement.
    const Quaternion i_rotation_j = rotation_i.conjugate() * rotation_j;
    const Vector i_translation_j =
        rotation_i.conjugate() * (translation_j - translation_i);
    const Quaternion measured_inverse(rotation.transpose().cast<T>());
    const Quaternion error_rotation = measured_inverse * i_rotation_j;
    const Vector error_translation =
        measured_inverse * (i_translation_j - translation.cast<T>());
    // Rotation vector of the error; ceres' convention is w, x, y, z.
    const T wxyz[4] = {error_rotation.w(),
                       error_rotation.x(),
                       error_rotation.y(),
                       error_rotation.z()};
    T angle_axis[3];
    ceres::QuaternionToAngleAxis(wxyz, angle_axis);
    for (int k = 0; k < 3; ++k) {
      residual[k] = error_translation[k] * T(inv_sigma_m);
      residual[3 + k] = angle_axis[k] * T(inv_sigma_rad);
    }
    return true;
  }

  Eigen::Matrix3d rotation;
  Vector3d translation;
  double inv_sigma_m;
  double inv_sigma_rad;
};

void EnsureQuaternionManifold(double* rotation, ceres::Problem* problem) {
  if (problem->GetManifold(rotation) == nullptr) {
    problem->SetManifold(rotation, new ceres::EigenQuaternionManifold);
  }
}

}  // namespace

PoseBlocks PoseBlocks::From(const Isometry3d& world_from_scan) {
  PoseBlocks blocks;
  Eigen::Map<Eigen::Quaterniond>(blocks.rotation) =
      Eigen::Quaterniond(world_from_scan.linear()).normalized();
  Eigen::Map<Vector3d>(blocks.translation) = world_from_scan.translation();
  return blocks;
}

Isometry3d PoseBlocks::ToIsometry() const {
  Isometry3d out = Isometry3d::Identity();
  out.linear() = Eigen::Map<const Eigen::Quaterniond>(rotation)
                     .normalized()
                     .toRotationMatrix();
  out.translation() = Eigen::Map<const Vector3d>(translation);
  return out;
}

ceres::ResidualBlockId AddOdometryFactor(const Isometry3d& measured_i_from_j,
                                         const OdometryNoise& noise,
                                         PoseBlocks* pose_i,
                                         PoseBlocks* pose_j,
                                         ceres::Problem* problem) {
  auto* cost = new ceres::AutoDiffCostFunction<OdometryFactor, 6, 4, 3, 4, 3>(
      new OdometryFactor(measured_i_from_j, noise));
  const ceres::ResidualBlockId id =
      problem->AddResidualBlock(cost,
                                nullptr,
                                pose_i->rotation,
                                pose_i->translation,
                                pose_j->rotation,
                                pose_j->translation);
  EnsureQuaternionManifold(pose_i->rotation, problem);
  EnsureQuaternionManifold(pose_j->rotation, problem);
  return id;
}

}  // namespace mlndt
