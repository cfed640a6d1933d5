// mlndt_lab.ScanStore, PairResult, run_sequence and chain_trajectory: the
// sequence run of mlndt_sequence (lab/runs/sequence_registration.h), scan
// i + step onto scan i, on maps the store builds once (Section 4.3).

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "lab/python/src/lab_module.h"
#include "lab/runs/scan_store.h"
#include "lab/runs/sequence_registration.h"
#include "python/src/arrays.h"
#include "python/src/errors.h"
#include "python/src/module.h"
#include "python/src/options.h"

namespace mlndt {
namespace python {
namespace {

// The store and the lock that serialises its use (ScanStore is not
// thread-safe; run_sequence releases the GIL).
struct PyScanStore {
  explicit PyScanStore(std::vector<std::string> paths)
      : store(std::move(paths)) {}
  ScanStore store;
  std::mutex mutex;
};

std::shared_ptr<PyScanStore> MakeStore(const py::iterable& paths) {
  std::vector<std::string> list;
  for (const py::handle path : paths) {
    list.push_back(PathString(py::reinterpret_borrow<py::object>(path)));
    if (!std::filesystem::is_regular_file(list.back())) {
      PyErr_SetString(PyExc_FileNotFoundError,
                      ("paths[" + std::to_string(list.size() - 1) +
                       "]: " + list.back() + ": no such file")
                          .c_str());
      throw py::error_already_set();
    }
  }
  return std::make_shared<PyScanStore>(std::move(list));
}

py::array_t<double> StoreCloud(PyScanStore& s, size_t i) {
  if (i >= s.store.size()) {
    throw py::index_error("scan " + std::to_string(i) + " of a store of " +
                          std::to_string(s.store.size()));
  }
  std::string error;
  const PointCloud* cloud = nullptr;
  {
    py::gil_scoped_release release;
    const std::lock_guard<std::mutex> lock(s.mutex);
    cloud = s.store.Cloud(i, &error);
  }
  if (cloud == nullptr) ThrowReadError(s.store.path(i), error);
  return PointsToPython(*cloud);
}

InitSpec ParseInit(const std::string& text, bool has_truth, bool has_odometry) {
  InitSpec spec;
  std::string error;
  if (text == "poses") {
    spec.mode = InitMode::POSES;
  } else if (text.rfind("poses:", 0) == 0 ||
             !ParseInitSpec(text, &spec, &error)) {
    throw py::value_error("init = '" + text +
                          "': expected zero, gt_fraction:c, "
                          "constant_velocity or poses (with odometry=)");
  }
  if (spec.mode == InitMode::GT_FRACTION && !has_truth) {
    throw py::value_error("init = '" + text + "' needs truth=");
  }
  if (spec.mode == InitMode::POSES && !has_odometry) {
    throw py::value_error("init = 'poses' needs odometry=");
  }
  return spec;
}

// One pose per scan, or a ValueError naming `what`.
std::vector<Isometry3d> ScanPoses(const py::object& poses,
                                  const char* what,
                                  size_t num_scans) {
  std::vector<Isometry3d> list = PosesFromPython(poses, what);
  if (list.size() < num_scans) {
    throw py::value_error(std::string(what) + ": " +
                          std::to_string(list.size()) + " poses for " +
                          std::to_string(num_scans) + " scans");
  }
  return list;
}

std::vector<PairResult> RunSequencePython(const py::object& scans,
                                          const py::object& truth,
                                          const py::object& odometry,
                                          int step,
                                          const std::string& init,
                                          bool adaptive_start_layer,
                                          const py::object& initial_uncertainty,
                                          const py::kwargs& kwargs) {
  const std::shared_ptr<PyScanStore> store =
      py::isinstance<PyScanStore>(scans)
          ? scans.cast<std::shared_ptr<PyScanStore>>()
          : MakeStore(scans);
  const size_t n = store->store.size();
  if (step < 1 || static_cast<size_t>(step) >= n) {
    throw py::value_error("step = " + std::to_string(step) + ": must be >= 1 " +
                          "and less than the number of scans (" +
                          std::to_string(n) + ")");
  }
  SequenceOptions options;
  options.step = static_cast<size_t>(step);
  options.registration.method = Method::MLNDT;
  options.registration.mlndt =
      RegistrationOptionsFromPython(kwargs, initial_uncertainty, false);
  options.init = ParseInit(init, !truth.is_none(), !odometry.is_none());
  options.adaptive.enabled = adaptive_start_layer;
  const std::vector<Isometry3d> truth_poses =
      truth.is_none() ? std::vector<Isometry3d>()
                      : ScanPoses(truth, "truth", n);
  const std::vector<Isometry3d> odometry_poses =
      odometry.is_none() ? std::vector<Isometry3d>()
                         : ScanPoses(odometry, "odometry", n);
  std::vector<PairResult> results;
  std::string error;
  bool ok = false;
  {
    py::gil_scoped_release release;
    const std::lock_guard<std::mutex> lock(store->mutex);
    ok = RunSequence(options,
                     &store->store,
                     truth.is_none() ? nullptr : &truth_poses,
                     odometry.is_none() ? nullptr : &odometry_poses,
                     {},
                     &results,
                     &error);
  }
  if (!ok) throw py::value_error("run_sequence: " + error);
  return results;
}

void DefineStore(py::module_& m) {
  py::class_<PyScanStore, std::shared_ptr<PyScanStore>>(
      m,
      "ScanStore",
      "The scans of a sequence (lab/runs/scan_store.h): each scan is read "
      "once and each\nscan's map built once per set of map options, "
      "reused by every run_sequence given\nthis store.")
      .def(py::init(&MakeStore),
           py::arg("paths"),
           "ScanStore(paths)\n\nScan files in sequence order. "
           "FileNotFoundError naming paths[i] for a missing one.")
      .def("__len__", [](PyScanStore& s) { return s.store.size(); })
      .def(
          "path",
          [](PyScanStore& s, size_t i) {
            if (i >= s.store.size()) throw py::index_error("scan index");
            return s.store.path(i);
          },
          py::arg("i"),
          "path(i) -> str")
      .def("cloud",
           &StoreCloud,
           py::arg("i"),
           "cloud(i) -> numpy.ndarray\n\nScan i as (N, 3) float64 (read on "
           "first use). OSError when it cannot be read.")
      .def_property_readonly(
          "num_maps_built",
          [](PyScanStore& s) {
            const std::lock_guard<std::mutex> lock(s.mutex);
            return s.store.num_maps_built();
          },
          "Maps the store has built in all.");
}

void DefinePairResult(py::module_& m) {
  const auto matrix = [](Isometry3d PairResult::*field) {
    return [field](const PairResult& r) {
      return Eigen::Matrix4d((r.*field).matrix());
    };
  };
  py::class_<PairResult>(m,
                         "PairResult",
                         "One pair of a sequence run (lab PairResult): scan "
                         "`input` registered onto\nscan `reference`; poses "
                         "are reference_from_input (4x4).")
      .def_readonly("reference", &PairResult::reference)
      .def_readonly("input", &PairResult::input)
      .def_property_readonly("guess", matrix(&PairResult::guess))
      .def_property_readonly("estimate", matrix(&PairResult::estimate))
      .def_readonly("has_truth", &PairResult::has_truth)
      .def_property_readonly("truth", matrix(&PairResult::truth))
      .def_property_readonly(
          "translation_error_m",
          [](const PairResult& r) { return r.error.translation_m; })
      .def_property_readonly(
          "rotation_error_deg",
          [](const PairResult& r) { return r.error.rotation_deg(); })
      .def_readonly("success",
                    &PairResult::success,
                    "Translation error < 0.5 m (with truth).")
      .def_readonly("strict_success",
                    &PairResult::strict_success,
                    "< 0.2 m and < 1 deg (with truth).")
      .def_property_readonly("termination",
                             [](const PairResult& r) {
                               return std::string(TerminationTypeToString(
                                   r.registration.termination_type));
                             })
      .def_property_readonly(
          "message", [](const PairResult& r) { return r.registration.message; })
      .def_property_readonly(
          "iterations",
          [](const PairResult& r) { return r.registration.num_iterations; })
      .def_property_readonly(
          "start_layer",
          [](const PairResult& r) { return r.registration.start_layer; })
      .def_property_readonly(
          "num_layers",
          [](const PairResult& r) { return r.registration.num_layers; })
      .def_property_readonly(
          "sampled_points",
          [](const PairResult& r) { return r.registration.sampled_points; })
      .def_property_readonly(
          "total_ms", [](const PairResult& r) { return r.times.total_ms; })
      .def_property_readonly("map_ms",
                             [](const PairResult& r) { return r.times.map_ms; })
      .def("__repr__", [](const PairResult& r) {
        return "<mlndt_lab.PairResult " + std::to_string(r.reference) + "->" +
               std::to_string(r.input) + " " +
               TerminationTypeToString(r.registration.termination_type) + ">";
      });
}

}  // namespace

void DefineSequence(py::module_& m) {
  DefineStore(m);
  DefinePairResult(m);
  m.def("run_sequence",
        &RunSequencePython,
        py::arg("scans"),
        py::arg("truth") = py::none(),
        py::arg("odometry") = py::none(),
        py::arg("step") = 1,
        py::arg("init") = "zero",
        py::arg("adaptive_start_layer") = false,
        py::arg("initial_uncertainty") = py::none(),
        ("run_sequence(scans, truth=None, odometry=None, step=1, "
         "init=\"zero\",\n             adaptive_start_layer=False, "
         "initial_uncertainty=None, **options)\n"
         "    -> list[PairResult]\n\n"
         "Registers scan i + step onto scan i for every i (mlndt_sequence's "
         "run, ML-NDT).\n"
         "scans: a ScanStore (its maps are reused across calls) or scan "
         "paths.\n"
         "truth, odometry: (N, 4, 4) world_from_scan per scan, or None.\n"
         "init: zero | gt_fraction:c (needs truth) | constant_velocity | "
         "poses (the\n    relative motions of odometry).\n"
         "adaptive_start_layer: the paper's rule (end of Section 5.3).\n"
         "**options: RegistrationOptions fields, as mlndt.register.\n"
         "Raises ValueError naming the argument or option; "
         "FileNotFoundError for a\nmissing scan; ValueError "
         "(run_sequence: ...) for a scan that cannot be read.\n\n"
         "Options (RegistrationOptions fields, nested ones as dicts):\n" +
         RegistrationOptionsDoc())
            .c_str());
  m.def(
      "chain_trajectory",
      [](const std::vector<PairResult>& results, int step, bool use_truth) {
        if (step < 1) throw py::value_error("step: must be >= 1");
        return PosesToPython(
            ChainTrajectory(results, static_cast<size_t>(step), use_truth));
      },
      py::arg("results"),
      py::arg("step") = 1,
      py::arg("use_truth") = false,
      "chain_trajectory(results, step=1, use_truth=False) -> numpy.ndarray\n\n"
      "Chains the estimates (or the truths) of a run into poses of scans 0, "
      "step,\n2 step, ... relative to scan 0 ((K, 4, 4); mlndt_sequence's "
      "trajectory_kitti.txt).");
}

}  // namespace python
}  // namespace mlndt
