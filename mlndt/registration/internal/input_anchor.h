#pragma once

// The pose is solved about the centroid c of the sampled input points, not
// about the input frame's origin: with the input points p = c + p_local,
//   R p + t = R p_local + t_local,   t_local = R c + t.
// In coordinates far from the origin (a UTM or projected map frame, 1e5 m
// and more) a rotation about the origin is a lever of that length: the
// solvers see rotations and translations scaled 1e5 apart and the step
// tolerance loses its meaning. About the centroid the lever is the scan's
// own extent. The angles are the same in both parametrisations.

#include "mlndt/common/pose.h"
#include "mlndt/common/types.h"
#include "mlndt/cost/transform_derivatives.h"

namespace mlndt {
namespace internal {

class InputAnchor {
 public:
  explicit InputAnchor(const Eigen::Vector3d& centre) : centre_(centre) {}
  const Eigen::Vector3d& centre() const { return centre_; }

  // xi about the input origin -> xi about the centre, and back.
  Vector6d ToLocal(const Vector6d& xi) const {
    Vector6d local = xi;
    local.head<3>() += EulerRotation(xi(3), xi(4), xi(5)) * centre_;
    return local;
  }
  Vector6d ToGlobal(const Vector6d& local) const {
    Vector6d xi = local;
    xi.head<3>() -= EulerRotation(local(3), local(4), local(5)) * centre_;
    return xi;
  }
  // d xi / d xi_local at `local`: [I, -dR/dangles c; 0, I].
  Matrix6d Jacobian(const Vector6d& local) const {
    Matrix6d j = Matrix6d::Identity();
    j.topRightCorner<3, 3>() =
        -TransformDerivatives(local).AngleJacobian(centre_);
    return j;
  }

 private:
  Eigen::Vector3d centre_;
};

}  // namespace internal
}  // namespace mlndt
