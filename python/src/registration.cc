#include "python/src/registration.h"

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <utility>

#include "mlndt/common/result_table.h"
#include "mlndt/registration/registration.h"
#include "python/src/arrays.h"
#include "python/src/module.h"
#include "python/src/options.h"
#include "python/src/result_binding.h"

namespace mlndt {
namespace python {
namespace {

using Summary = RegistrationSummary;

py::object Register(const py::object& reference,
                    const py::object& input,
                    const py::object& initial,
                    const py::object& initial_uncertainty,
                    const py::kwargs& kwargs) {
  const RegistrationOptions options =
      RegistrationOptionsFromPython(kwargs, initial_uncertainty, false);
  const Isometry3d guess = TransformFromPython(initial, "initial");
  const PointCloud reference_cloud =
      PointsFromPython(reference, "reference", false);
  const PointCloud input_cloud = PointsFromPython(input, "input", false);
  return py::cast(RegisterReleasingGil(
      options, nullptr, &reference_cloud, input_cloud, guess));
}

void DefineResult(py::module_& m) {
  py::class_<Summary> result(
      m,
      "RegistrationResult",
      "What a registration reports (mlndt::RegistrationSummary): the pose, "
      "the verdict, the fit, the covariance, the trace and timings. Poses "
      "map input points into the reference frame. The properties are the "
      "struct's fields (RegistrationSummaryTable()), named and in the units "
      "of the C++ struct (m, rad, s); todict() gives them all, as "
      "mlndt_align's JSON \"registration\" does.");
  DefineResultProperties(result, RegistrationSummaryTable());
  result
      .def_property_readonly(
          "converged",
          [](const Summary& s) {
            return s.termination_type == TerminationType::CONVERGENCE;
          },
          "termination_type == \"CONVERGENCE\".")
      .def("report",
           &Summary::FullReport,
           "report() -> str\n\nThe library's FullReport (what mlndt_align "
           "prints).")
      .def("brief_report",
           &Summary::BriefReport,
           "brief_report() -> str\n\nThe library's one-line BriefReport.")
      .def("__repr__", [](const Summary& s) {
        return "<mlndt.RegistrationResult " + s.BriefReport() + ">";
      });
}

}  // namespace

RegistrationSummary RegisterReleasingGil(const RegistrationOptions& options,
                                         const LayeredGrid* map,
                                         const PointCloud* reference,
                                         const PointCloud& input,
                                         const Isometry3d& initial) {
  RegistrationSummary summary;
  py::gil_scoped_release release;
  if (map != nullptr) {
    mlndt::Register(options, *map, input, initial, &summary);
  } else {
    mlndt::Register(options, *reference, input, initial, &summary);
  }
  return summary;
}

std::string RegisterArgumentsDoc() {
  return "initial: 4x4 (or 3x4) rigid transform, the guess of "
         "reference_from_input\n"
         "    (maps input points into the reference frame); None: "
         "identity.\n"
         "initial_uncertainty: (translation_m, rotation_deg), how far the "
         "guess may be\n"
         "    off: picks the start layer and a guess is never made worse; "
         "None: unknown.\n"
         "preset: \"default\" (RegistrationOptions()) or \"paper\"\n"
         "    (PaperRegistrationOptions()); the other options change it.\n"
         "\n"
         "Options are keyword arguments named as the fields of "
         "mlndt::RegistrationOptions;\n"
         "a nested struct is a dict of its fields (only those given "
         "change), enums are\n"
         "strings in any case, e.g. grid={\"finest_cell_size_m\": 1.0}, "
         "backend={\"type\": \"lm\"}.\n"
         "mlndt.default_options() returns them all. The library's IsValid "
         "checks them.\n" +
         RegistrationOptionsDoc() +
         "\n"
         "Returns a RegistrationResult. A registration that ends badly is "
         "not an exception:\n"
         "its termination says FAILURE, LOW_QUALITY or DEGENERATE and its "
         "message why;\n"
         "check result.usable.\n"
         "\n"
         "Raises ValueError for an unknown option or an invalid value "
         "(naming the field),\n"
         "a cloud of the wrong shape, an empty cloud, a non-finite row or a "
         "guess that is\n"
         "not a rigid transform; TypeError for a non-numeric array.\n"
         "\n"
         "The GIL is released while the library runs: threads register in "
         "parallel.\n";
}

void DefineRegistration(py::module_& m) {
  DefineResult(m);
  m.def("register",
        &Register,
        py::arg("reference"),
        py::arg("input"),
        py::arg("initial") = py::none(),
        py::arg("initial_uncertainty") = py::none(),
        ("register(reference, input, initial=None, initial_uncertainty=None, "
         "**options) -> RegistrationResult\n\n"
         "Registers the input scan onto the reference scan with ML-NDT "
         "(mlndt::Register):\n"
         "builds the layered map of the reference, samples the input and "
         "runs the layer\n"
         "schedule (Table 1).\n"
         "\n"
         "reference, input: (N, 3) arrays of x, y, z [m], float64 or float32, "
         "any strides\n"
         "    (copied once into the library's clouds; float32 converted on "
         "the way).\n" +
         RegisterArgumentsDoc())
            .c_str());
}

}  // namespace python
}  // namespace mlndt
