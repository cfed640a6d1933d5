#include "python/src/arrays.h"

#include <cmath>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "mlndt/common/rigid_transform.h"

namespace mlndt {
namespace python {
namespace {

static_assert(sizeof(Eigen::Vector3d) == 3 * sizeof(double),
              "PointCloud's points must be three packed doubles");

std::string ShapeString(const py::array& array) {
  std::string shape = "(";
  for (py::ssize_t i = 0; i < array.ndim(); ++i) {
    shape += (i ? ", " : "") + std::to_string(array.shape(i));
  }
  return shape + (array.ndim() == 1 ? ",)" : ")");
}

// An ndarray of float32 or float64 in native byte order: `value` itself when
// it is one, else converted once (lists, integer dtypes, float16, ...).
py::array AsRealArray(py::handle value, const char* what) {
  const py::module_ numpy = py::module_::import("numpy");
  py::array array;
  if (py::isinstance<py::array>(value)) {
    array = py::reinterpret_borrow<py::array>(value);
  } else {
    try {
      array = numpy.attr("asarray")(value);
    } catch (py::error_already_set&) {
      throw py::type_error(std::string(what) +
                           ": expected an (N, 3) array of points");
    }
  }
  const char kind = array.dtype().kind();
  const py::ssize_t size = array.dtype().itemsize();
  const bool native = array.dtype().attr("isnative").cast<bool>();
  if (kind == 'f' && (size == 4 || size == 8) && native) return array;
  if (kind == 'f' || kind == 'i' || kind == 'u') {
    return numpy.attr("asarray")(array, numpy.attr("float64"));
  }
  throw py::type_error(std::string(what) +
                       ": expected a float64 or float32 array of shape (N, "
                       "3), got dtype " +
                       py::str(array.dtype()).cast<std::string>());
}

// Copies the rows of an (N, 3) array of T with any strides.
template <typename T>
void CopyRows(const py::array& array, std::vector<Eigen::Vector3d>* points) {
  const char* data = static_cast<const char*>(array.data());
  const py::ssize_t row_stride = array.strides(0);
  const py::ssize_t column_stride = array.strides(1);
  const size_t n = static_cast<size_t>(array.shape(0));
  if (std::is_same_v<T, double> && row_stride == 3 * sizeof(double) &&
      column_stride == sizeof(double)) {
    // Vector3d is three packed doubles (static_assert above).
    std::memcpy(
        static_cast<void*>(points->data()), data, n * 3 * sizeof(double));
    return;
  }
  for (size_t i = 0; i < n; ++i) {
    const char* row = data + static_cast<py::ssize_t>(i) * row_stride;
    for (int a = 0; a < 3; ++a) {
      T value;  // memcpy: the array need not be aligned.
      std::memcpy(&value, row + a * column_stride, sizeof(T));
      (*points)[i](a) = static_cast<double>(value);
    }
  }
}

}  // namespace

PointCloud PointsFromPython(py::handle points,
                            const char* what,
                            bool allow_empty) {
  const py::array array = AsRealArray(points, what);
  if (array.ndim() != 2 || array.shape(1) != 3) {
    std::string hint;
    if (array.ndim() == 2 && array.shape(0) == 3) {
      hint = " (one point per column? pass points.T)";
    } else if (array.ndim() == 2 && array.shape(1) > 3) {
      hint = " (x, y, z first? pass points[:, :3])";
    }
    throw py::value_error(std::string(what) +
                          ": expected an array of shape (N, 3), got shape " +
                          ShapeString(array) + hint);
  }
  const size_t n = static_cast<size_t>(array.shape(0));
  if (n == 0 && !allow_empty) {
    throw py::value_error(std::string(what) + ": no points (shape " +
                          ShapeString(array) + ")");
  }
  std::vector<Eigen::Vector3d> copied(n);
  if (array.dtype().itemsize() == 8) {
    CopyRows<double>(array, &copied);
  } else {
    CopyRows<float>(array, &copied);
  }
  for (size_t i = 0; i < n; ++i) {
    if (!copied[i].allFinite()) {
      std::ostringstream message;
      message << what << ": row " << i << " is not finite (" << copied[i](0)
              << ", " << copied[i](1) << ", " << copied[i](2)
              << "); drop such rows first, e.g. "
                 "points[np.isfinite(points).all(axis=1)]";
      throw py::value_error(message.str());
    }
  }
  return PointCloud(std::move(copied));
}

py::array_t<double> PointsToPython(PointCloud cloud) {
  auto* points =
      new std::vector<Eigen::Vector3d>(std::move(*cloud.mutable_points()));
  py::capsule owner(points, [](void* p) {
    delete static_cast<std::vector<Eigen::Vector3d>*>(p);
  });
  const py::ssize_t n = static_cast<py::ssize_t>(points->size());
  return py::array_t<double>({n, py::ssize_t{3}},
                             {static_cast<py::ssize_t>(3 * sizeof(double)),
                              static_cast<py::ssize_t>(sizeof(double))},
                             points->empty() ? nullptr : points->front().data(),
                             owner);
}

Isometry3d TransformFromPython(py::handle matrix, const char* what) {
  if (matrix.is_none()) return Isometry3d::Identity();
  const py::array array = AsRealArray(matrix, what);
  const bool rows_ok =
      array.ndim() == 2 && (array.shape(0) == 3 || array.shape(0) == 4);
  if (!rows_ok || array.shape(1) != 4) {
    throw py::value_error(std::string(what) +
                          ": expected a 4x4 (or 3x4) rigid transform, got "
                          "shape " +
                          ShapeString(array));
  }
  const py::array_t<double> values =
      py::array_t<double, py::array::forcecast>::ensure(array);
  const auto m = values.unchecked<2>();
  Eigen::Matrix4d t = Eigen::Matrix4d::Identity();
  for (py::ssize_t r = 0; r < array.shape(0); ++r) {
    for (int c = 0; c < 4; ++c) t(r, c) = m(r, c);
  }
  if (!t.allFinite()) {
    throw py::value_error(std::string(what) + ": has non-finite entries");
  }
  if ((t.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).norm() > 1e-12) {
    throw py::value_error(std::string(what) +
                          ": the last row of a 4x4 transform must be "
                          "[0, 0, 0, 1]");
  }
  // The library's one check and re-orthonormalisation (rigid_transform.h).
  Isometry3d transform;
  std::string problem;
  if (!ToRigidTransform(t, &transform, &problem)) {
    throw py::value_error(std::string(what) + ": not a rigid transform (" +
                          problem + ")");
  }
  return transform;
}

}  // namespace python
}  // namespace mlndt
