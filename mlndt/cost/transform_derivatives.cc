#include "mlndt/cost/transform_derivatives.h"

#include <cmath>

namespace mlndt {
namespace {

// Elementary rotation about `axis` (0 = x, 1 = y, 2 = z) by `angle`, and its
// first and second derivatives with respect to the angle.
void Elementary(
    int axis, double angle, Matrix3d* r, Matrix3d* d1, Matrix3d* d2) {
  const double c = std::cos(angle), s = std::sin(angle);
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;  // The rotated plane.
  r->setIdentity();
  d1->setZero();
  d2->setZero();
  (*r)(i, i) = c;
  (*r)(i, j) = -s;
  (*r)(j, i) = s;
  (*r)(j, j) = c;
  (*d1)(i, i) = -s;
  (*d1)(i, j) = -c;
  (*d1)(j, i) = c;
  (*d1)(j, j) = -s;
  (*d2)(i, i) = -c;
  (*d2)(i, j) = s;
  (*d2)(j, i) = -s;
  (*d2)(j, j) = -c;
}

}  // namespace

TransformDerivatives::TransformDerivatives(const Vector6d& xi)
    : translation_(xi.head<3>()) {
  // factors[axis][order]: the elementary rotation (order 0) and derivatives.
  Matrix3d factors[3][3];
  for (int axis = 0; axis < 3; ++axis) {
    Elementary(axis,
               xi(3 + axis),
               &factors[axis][0],
               &factors[axis][1],
               &factors[axis][2]);
  }
  // R with each factor differentiated `order[axis]` times.
  const auto product = [&factors](int ox, int oy, int oz) -> Matrix3d {
    return factors[0][ox] * factors[1][oy] * factors[2][oz];
  };
  rotation_ = product(0, 0, 0);
  first_[0] = product(1, 0, 0);
  first_[1] = product(0, 1, 0);
  first_[2] = product(0, 0, 1);
  for (int k = 0; k < 3; ++k) {
    for (int l = k; l < 3; ++l) {
      int order[3] = {0, 0, 0};
      ++order[k];
      ++order[l];
      second_[k][l] = product(order[0], order[1], order[2]);
      second_[l][k] = second_[k][l];
    }
  }
}

Eigen::Matrix<double, 3, 6> TransformDerivatives::Jacobian(
    const Eigen::Vector3d& x) const {
  Eigen::Matrix<double, 3, 6> jacobian;
  jacobian.leftCols<3>().setIdentity();
  jacobian.rightCols<3>() = AngleJacobian(x);
  return jacobian;
}

Matrix6d TransformDerivatives::WeightedSecondDerivative(
    const Eigen::Vector3d& x, const Eigen::Vector3d& w) const {
  Matrix6d h = Matrix6d::Zero();
  for (int k = 0; k < 3; ++k) {
    for (int l = k; l < 3; ++l) {
      h(3 + k, 3 + l) = w.dot(second_[k][l] * x);
      h(3 + l, 3 + k) = h(3 + k, 3 + l);
    }
  }
  return h;
}

}  // namespace mlndt
