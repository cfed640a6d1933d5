#pragma once

// numpy arrays <-> the library's point clouds and transforms.
//
// Points come in as (N, 3) arrays. PointCloud owns its points (a
// std::vector<Eigen::Vector3d>, 24 bytes a point), so they are copied once:
// a C-contiguous float64 array with one memcpy, float32 and strided
// (non-contiguous, Fortran-order, sliced) arrays element by element in the
// same single pass, any other real dtype (and nested lists) converted to
// float64 first. Points go out without a copy: the array views the cloud's
// vector and owns it.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "mlndt/cloud/point_cloud.h"
#include "mlndt/common/types.h"

namespace mlndt {
namespace python {

namespace py = pybind11;

// `what` names the argument in messages ("reference", "input"). Raises
// ValueError for a wrong shape, an empty array (unless `allow_empty`) and a
// non-finite row (naming it), TypeError for a non-numeric array.
PointCloud PointsFromPython(py::handle points,
                            const char* what,
                            bool allow_empty);

// An (N, 3) float64 array that owns the cloud's points (no copy).
py::array_t<double> PointsToPython(PointCloud cloud);

// None -> identity; a 4x4 (last row 0 0 0 1) or 3x4 rigid transform.
// Raises ValueError for another shape, non-finite entries or a matrix that
// is not a rotation (|R^T R - I| > 1e-6 or det R < 0, the library's test).
Isometry3d TransformFromPython(py::handle matrix, const char* what);

}  // namespace python
}  // namespace mlndt
