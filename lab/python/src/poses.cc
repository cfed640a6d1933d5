// Pose lists <-> (N, 4, 4) arrays (lab_module.h).

#include <pybind11/numpy.h>

#include <string>
#include <vector>

#include "lab/python/src/lab_module.h"
#include "python/src/arrays.h"

namespace mlndt {
namespace python {

std::vector<Isometry3d> PosesFromPython(py::handle poses, const char* what) {
  if (poses.is_none() || py::isinstance<py::str>(poses) ||
      !py::isinstance<py::sequence>(poses)) {
    throw py::type_error(std::string(what) +
                         ": expected an (N, 4, 4) array of poses, got " +
                         py::repr(poses).cast<std::string>());
  }
  const py::sequence rows = py::reinterpret_borrow<py::object>(poses);
  std::vector<Isometry3d> result;
  result.reserve(rows.size());
  for (size_t k = 0; k < rows.size(); ++k) {
    const std::string name = std::string(what) + "[" + std::to_string(k) + "]";
    result.push_back(TransformFromPython(rows[k], name.c_str()));
  }
  return result;
}

py::array_t<double> PosesToPython(const std::vector<Isometry3d>& poses) {
  const py::ssize_t n = static_cast<py::ssize_t>(poses.size());
  py::array_t<double> array({n, py::ssize_t{4}, py::ssize_t{4}});
  auto out = array.mutable_unchecked<3>();
  for (py::ssize_t k = 0; k < n; ++k) {
    const Eigen::Matrix4d& m = poses[static_cast<size_t>(k)].matrix();
    for (int r = 0; r < 4; ++r) {
      for (int c = 0; c < 4; ++c) out(k, r, c) = m(r, c);
    }
  }
  return array;
}

}  // namespace python
}  // namespace mlndt
