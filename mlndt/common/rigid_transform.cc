#include "mlndt/common/rigid_transform.h"

#include <glog/logging.h>

#include <Eigen/SVD>
#include <cmath>
#include <sstream>

namespace mlndt {

bool ToRigidTransform(const Eigen::Matrix4d& matrix,
                      Isometry3d* rigid,
                      std::string* problem) {
  CHECK(rigid != nullptr);
  CHECK(problem != nullptr);
  if (!matrix.allFinite()) {
    *problem = "non-finite number";
    return false;
  }
  if ((matrix.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).norm() > 1e-12) {
    *problem = "the last row is not 0 0 0 1";
    return false;
  }
  const Eigen::Vector3d t = matrix.topRightCorner<3, 1>();
  if (t.cwiseAbs().maxCoeff() > kMaxCoordinateM) {
    std::ostringstream message;
    message << "translation (" << t.x() << ", " << t.y() << ", " << t.z()
            << ") m is beyond " << kMaxCoordinateM << " m (not a place)";
    *problem = message.str();
    return false;
  }
  const Eigen::Matrix3d r = matrix.topLeftCorner<3, 3>();
  const double orthogonality =
      (r.transpose() * r - Eigen::Matrix3d::Identity()).norm();
  if (!(orthogonality <= kRigidRotationTolerance) || r.determinant() <= 0.0) {
    std::ostringstream message;
    message << "the 3x3 part is not a rotation (|R^T R - I| = " << orthogonality
            << ", allowed " << kRigidRotationTolerance
            << "; det R = " << r.determinant()
            << "): give a rotation, not a reflection or a scaled matrix";
    *problem = message.str();
    return false;
  }
  rigid->setIdentity();
  rigid->translation() = t;
  // A rotation exact to rounding (from angles, or written with %.17g) is
  // kept bit for bit; anything coarser is replaced by the nearest rotation.
  if (orthogonality <= 1e-12) {
    rigid->linear() = r;
    return true;
  }
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(
      r, Eigen::ComputeFullU | Eigen::ComputeFullV);
  rigid->linear() = svd.matrixU() * svd.matrixV().transpose();
  return true;
}

}  // namespace mlndt
