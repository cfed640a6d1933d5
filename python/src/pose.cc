// mlndt.pose_from_xi and xi_from_pose: the paper's pose vector (Eq. 11)
// and 4x4 transforms (common/pose.h).

#include "mlndt/common/pose.h"

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>

#include "python/src/arrays.h"
#include "python/src/module.h"
#include "python/src/option_binding.h"

namespace mlndt {
namespace python {

void DefinePose(py::module_& m) {
  m.def(
      "pose_from_xi",
      [](const py::object& xi, bool degrees) {
        std::vector<double> v;
        if (!OptionCodec<std::vector<double>>::FromPython(xi, &v) ||
            v.size() != 6) {
          throw py::value_error(
              "xi: expected 6 numbers (tx, ty, tz, alpha, "
              "beta, gamma), got " +
              DescribeValue(xi));
        }
        const Vector6d pose =
            degrees ? PoseVectorFromDegrees(v[0], v[1], v[2], v[3], v[4], v[5])
                    : Vector6d(Eigen::Map<const Vector6d>(v.data()));
        return Eigen::Matrix4d(PoseVectorToIsometry(pose).matrix());
      },
      py::arg("xi"),
      py::arg("degrees") = false,
      "pose_from_xi(xi, degrees=False) -> numpy.ndarray\n\n"
      "The 4x4 transform of the pose vector xi = (tx, ty, tz, alpha, beta, "
      "gamma) (Eq. 11): x' = R x + t with R = Rx(alpha) Ry(beta) Rz(gamma) "
      "(Eq. 7). Metres and radians (degrees=True: the angles in degrees, "
      "as mlndt_align's --initial_guess).");
  m.def(
      "xi_from_pose",
      [](const py::object& matrix) {
        return Vector6d(
            IsometryToPoseVector(TransformFromPython(matrix, "pose")));
      },
      py::arg("pose"),
      "xi_from_pose(pose) -> numpy.ndarray\n\n"
      "The pose vector (tx, ty, tz, alpha, beta, gamma) of a 4x4 (or 3x4) "
      "rigid transform, metres and radians, beta in [-pi/2, pi/2] (the "
      "inverse of pose_from_xi).");
}

}  // namespace python
}  // namespace mlndt
