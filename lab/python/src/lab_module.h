#pragma once

// The parts of the lab module mlndt_lab._lab (lab/python/mlndt_lab/__init__.py
// re-exports it): the lab's evaluation (lab/eval) and sequence runs (lab/runs)
// on numpy arrays. Kept apart from python/src, which binds the installed
// library only (scripts/check_boundaries.sh).

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "mlndt/common/types.h"

namespace mlndt {
namespace python {

namespace py = pybind11;

void DefineEvaluation(py::module_& m);       // evaluation.cc
void DefineTrajectoryFiles(py::module_& m);  // trajectory_files.cc
void DefineSequence(py::module_& m);         // sequence.cc
void DefineRosBag(py::module_& m);           // ros_bag.cc

// An (N, 4, 4) or (N, 3, 4) array (or a list of 4x4 matrices) of rigid
// transforms; `what` names the argument in errors ("reference[3]: ...").
// ValueError for another shape or a transform that is not rigid.
std::vector<Isometry3d> PosesFromPython(py::handle poses, const char* what);

// An (N, 4, 4) float64 array.
py::array_t<double> PosesToPython(const std::vector<Isometry3d>& poses);

}  // namespace python
}  // namespace mlndt
