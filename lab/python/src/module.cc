// The lab module mlndt_lab._lab (lab/python/mlndt_lab/__init__.py re-exports
// it): the lab's trajectory evaluation and sequence runs (lab/), which the core
// module mlndt._mlndt must not include.

#include <pybind11/pybind11.h>

#include "lab/python/src/lab_module.h"

PYBIND11_MODULE(_lab, m) {
  namespace py = pybind11;
  py::options options;
  options.disable_function_signatures();
  m.doc() =
      "The mlndt lab on numpy arrays: trajectory evaluation (ATE, RPE, the "
      "KITTI devkit's\nsegment errors, association, KITTI/TUM files) and "
      "sequence runs (ScanStore,\nrun_sequence), as mlndt_eval and "
      "mlndt_sequence compute them, and ROS 1 bag reading\n(RosBag).";
  m.attr("__version__") = MLNDT_VERSION;
  mlndt::python::DefineEvaluation(m);
  mlndt::python::DefineTrajectoryFiles(m);
  mlndt::python::DefineSequence(m);
  mlndt::python::DefineRosBag(m);
}
