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
        true);
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
    localizer_->Localize(cloud, &result, nullptr);
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

py::dict QualityDict(const Result& r) {
  py::dict quality;
  quality["points"] = r.quality.points;
  quality["own_cell_fraction"] = r.quality.own_cell_fraction;
  quality["inlier_fraction"] = r.quality.inlier_fraction;
  quality["mean_score"] = r.quality.mean_score;
  quality["median_distance"] = r.quality.median_distance;
  return quality;
}

void DefineResult(py::module_& m) {
  py::class_<Result>(m,
                     "LocalizationResult",
                     "One scan's localisation (mlndt::LocalizationResult): "
                     "the prediction, the\nestimate, the verdict and the "
                     "fit. Poses are map_from_scan (4x4).")
      .def_readonly("index", &Result::index, "0-based scan index.")
      .def_property_readonly(
          "predicted_map_from_scan",
          [](const Result& r) {
            return Eigen::Matrix4d(r.predicted_map_from_scan.matrix());
          },
          "The initial guess (the motion model's prediction), 4x4.")
      .def_property_readonly(
          "map_from_scan",
          [](const Result& r) {
            return Eigen::Matrix4d(r.map_from_scan.matrix());
          },
          "The estimate, 4x4 (the prediction on FAILURE).")
      .def_property_readonly(
          "termination",
          [](const Result& r) {
            return std::string(TerminationTypeToString(r.termination_type));
          },
          "CONVERGENCE, NO_CONVERGENCE, FAILURE, LOW_QUALITY or DEGENERATE.")
      .def_property_readonly(
          "usable", &Result::IsSolutionUsable, "termination != FAILURE.")
      .def_readonly("message", &Result::message, "Why it ended.")
      .def_property_readonly(
          "quality",
          &QualityDict,
          "The fit at the solution (FitQuality: points, own_cell_fraction, "
          "inlier_fraction,\nmean_score, median_distance).")
      .def_readonly("iterations", &Result::iterations)
      .def_readonly("input_points", &Result::input_points)
      .def_readonly("sampled_points", &Result::sampled_points)
      .def_readonly("matched_points", &Result::matched_points)
      .def_readonly("score", &Result::final_score, "Eq. 10 at the solution.")
      .def_readonly("sampling_time_s", &Result::sampling_time_s)
      .def_readonly("solve_time_s", &Result::solve_time_s)
      .def_readonly("registration_time_s",
                    &Result::registration_time_s,
                    "The registration's total wall time [s].")
      .def("__repr__", [](const Result& r) {
        return "<mlndt.LocalizationResult scan " + std::to_string(r.index) +
               " " + TerminationTypeToString(r.termination_type) + ", " +
               std::to_string(r.iterations) + " iterations>";
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
