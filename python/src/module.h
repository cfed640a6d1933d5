#pragma once

// The parts of the mlndt Python module, one file each (module.cc puts them
// together). They are also linked into the lab module mlndt_lab._lab
// (lab/python/src/), which uses the converters and option parsers.

#include <pybind11/pybind11.h>

#include <string>

namespace mlndt {
namespace python {

namespace py = pybind11;

void DefineCloud(py::module_& m);         // cloud.cc
void DefineOptions(py::module_& m);       // options.cc
void DefinePose(py::module_& m);          // pose.cc
void DefineRegistration(py::module_& m);  // registration.cc
void DefineMap(py::module_& m);           // map.cc
void DefineLocalizer(py::module_& m);     // localizer.cc
void DefineOdometry(py::module_& m);      // odometry.cc

// A str or os.PathLike as a path string (TypeError otherwise; paths.cc).
std::string PathString(const py::object& path);

}  // namespace python
}  // namespace mlndt
