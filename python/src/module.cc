// The mlndt Python module (imported as mlndt._mlndt; python/mlndt/__init__.py
// re-exports it). Registration, maps, localisation, clouds and options of
// the C++ library; python/mlndt/__init__.pyi has the types for editors.

#include "python/src/module.h"

#include <pybind11/pybind11.h>

PYBIND11_MODULE(_mlndt, m) {
  namespace py = pybind11;
  // Every function writes its own signature line (the generated ones would
  // say "object" for array-likes and hide the options).
  py::options options;
  options.disable_function_signatures();
  m.doc() =
      "ML-NDT scan matching (Ulas & Temeltas 2013): the mlndt C++ library's "
      "registration, layered maps and cloud files on numpy arrays.";
  m.attr("__version__") = MLNDT_VERSION;
  mlndt::python::DefineOptions(m);
  mlndt::python::DefineCloud(m);
  mlndt::python::DefinePose(m);
  mlndt::python::DefineRegistration(m);
  mlndt::python::DefineMap(m);
  mlndt::python::DefineLocalizer(m);
  mlndt::python::DefineOdometry(m);
}
