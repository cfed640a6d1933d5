// mlndt.Localizer and mlndt.LocalizationResult: localisation of a scan
// sequence against one prebuilt map (pipeline/localizer.h), scan by scan,
// each scan starting from the motion model's prediction.

#include "mlndt/pipeline/localizer.h"

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <memory>
#include <mutex>
#include <string>

#include "mlndt/pipeline/pipeline_option_tables.h"
#include "python/src/arrays.h"
#include "python/src/map.h"
#include "python/src/module.h"
#include "python/src/option_binding.h"
#include "python/src/options.h"
#include "python/src/result_binding.h"

namespace mlndt {
namespace python {
namespace {

using Result = LocalizationResult;

// LocalizerOptions without the registration (LocalizerOwnOptionsTable).
const StructBinding<LocalizerOptions>& LocalizerOwnBinding() {
  static const StructBinding<LocalizerOptions> binding(
      LocalizerOwnOptionsTable());
  return binding;
}

// The default of an own field as its keyword's default ("constant_velocity").
std::string OwnDefault(const std::string& name) {
  const OptionTable& table = LocalizerOwnOptionsTable();
  return table.Find(name)->Format(table.defaults());
}

// Holds the map (shared with the LayeredMap it came from) for as long as
// the C++ Localizer refers to it; one Localize at a time (the motion model
// is state).
class PyLocalizer {
 public:
  PyLocalizer(const LayeredMap& map,
              const py::object& first_map_from_scan,
              const py::object& motion_model,
              const py::object& initial_uncertainty,
              const py::kwargs& kwargs)
      : grid_(map.grid_ptr()) {
    if (kwargs.contains("grid")) {
      throw py::value_error(
          "invalid option: grid does not apply to Localizer (the map is "
          "built already; give grid options to LayeredMap.build)");
    }
    // LocalizerOptions' own fields (motion_model and any other of its
    // table) apart from the registration's keywords.
    py::dict own;
    py::dict registration = py::dict(kwargs);  // A copy.
    own["motion_model"] = motion_model;
    for (const std::string& name : LocalizerOwnBinding().Names()) {
      if (!registration.contains(name)) continue;
      own[name.c_str()] = registration[name.c_str()];
      PyDict_DelItemString(registration.ptr(), name.c_str());
    }
    LocalizerOptions options;
    LocalizerOwnBinding().Update(own, "", &options);
    options.registration = RegistrationOptionsFromPython(
        py::reinterpret_borrow<py::kwargs>(registration),
        initial_uncertainty,
        true,
        LocalizerRegistrationOptions());
    std::string error;
    if (!options.IsValid(&error)) throw py::value_error(error);
    const Isometry3d first =
        TransformFromPython(first_map_from_scan, "first_map_from_scan");
    localizer_ = std::make_unique<Localizer>(options, *grid_, first);
  }

  Result Localize(const py::object& scan) {
    const PointCloud cloud = PointsFromPython(scan, "scan", false);
    Result result;
    py::gil_scoped_release release;
    const std::lock_guard<std::mutex> lock(mutex_);
    localizer_->Localize(cloud, &result);
    return result;
  }

  Eigen::Matrix4d PredictNext() {
    const std::lock_guard<std::mutex> lock(mutex_);
    return localizer_->PredictNext().matrix();
  }

  size_t num_localized() {
    const std::lock_guard<std::mutex> lock(mutex_);
    return localizer_->num_localized();
  }

 private:
  std::shared_ptr<const LayeredGrid> grid_;
  std::unique_ptr<Localizer> localizer_;
  std::mutex mutex_;
};

void DefineResult(py::module_& m) {
  py::class_<Result> result(
      m,
      "LocalizationResult",
      "One scan's localisation (mlndt::LocalizationResult): the prediction, "
      "the estimate and the registration's whole result. The properties are "
      "the struct's fields (LocalizationResultTable()), named and in the "
      "units of the C++ struct (m, rad, s); todict() gives them all, as a "
      "scan of mlndt_localize's scans.json does.");
  DefineResultProperties(result, LocalizationResultTable());
  result
      .def_property_readonly(
          "registration",
          [](const Result& r) -> const RegistrationSummary& {
            return r.registration;
          },
          py::return_value_policy::reference_internal,
          "The registration of the scan onto the map from the prediction: a "
          "RegistrationResult (todict()[\"registration\"] as a dict).")
      .def("__repr__", [](const Result& r) {
        return "<mlndt.LocalizationResult scan " + std::to_string(r.index) +
               " " + TerminationTypeToString(r.registration.termination_type) +
               ", " + std::to_string(r.registration.num_iterations) +
               " iterations>";
      });
}

// The constructor's doc: the own fields' from their table.
const std::string& LocalizerDoc() {
  static const std::string doc =
      "Localizer(map, first_map_from_scan=None, motion_model=\"" +
      OwnDefault("motion_model") +
      "\",\n"
      "          initial_uncertainty=None, **options)\n\n"
      "map: a LayeredMap (kept alive by the localizer).\n"
      "first_map_from_scan: 4x4 (or 3x4) guess of the first scan's pose; "
      "None: identity.\n"
      "LocalizerOptions' own keywords (lower-case enum names accepted; a "
      "FAILURE keeps\nits prediction as its pose and leaves the motion as it "
      "was):\n" +
      LocalizerOwnBinding().Describe(LocalizerOptions(), "    ") +
      "initial_uncertainty and **options: as LayeredMap.register "
      "(RegistrationOptions\n"
      "    fields; grid does not apply), used for every scan.\n"
      "Raises ValueError naming the option or argument that is invalid.";
  return doc;
}

}  // namespace

void DefineLocalizer(py::module_& m) {
  DefineResult(m);
  py::class_<PyLocalizer>(
      m,
      "Localizer",
      "Localisation of a scan sequence against one prebuilt map "
      "(mlndt::Localizer):\nscan k starts from the motion model's "
      "prediction and is registered onto the map.")
      .def(py::init<const LayeredMap&,
                    const py::object&,
                    const py::object&,
                    const py::object&,
                    const py::kwargs&>(),
           py::arg("map"),
           py::arg("first_map_from_scan") = py::none(),
           py::arg("motion_model") = OwnDefault("motion_model"),
           py::arg("initial_uncertainty") = py::none(),
           LocalizerDoc().c_str())
      .def("localize",
           &PyLocalizer::Localize,
           py::arg("scan"),
           "localize(scan) -> LocalizationResult\n\n"
           "Registers the next scan ((N, 3) array in its sensor frame) from "
           "predict_next()\nand updates the motion model (the GIL is "
           "released). Raises ValueError for a\nscan of the wrong shape, "
           "empty or with a non-finite row.")
      .def("predict_next",
           &PyLocalizer::PredictNext,
           "predict_next() -> numpy.ndarray\n\nThe 4x4 initial guess of the "
           "next scan.")
      .def_property_readonly("num_localized",
                             &PyLocalizer::num_localized,
                             "Scans localised so far.");
}

}  // namespace python
}  // namespace mlndt
