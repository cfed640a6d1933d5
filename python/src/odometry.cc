// mlndt.Odometry, mlndt.OdometryResult and mlndt.run_odometry: the
// scan-to-local-map odometry of the installed library (mlndt/odometry/),
// scan by scan or over a whole sequence, as mlndt_odometry runs it.

#include "mlndt/odometry/odometry.h"

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "mlndt/cloud/io.h"
#include "mlndt/odometry/odometry_option_tables.h"
#include "mlndt/odometry/run_odometry.h"
#include "python/src/arrays.h"
#include "python/src/errors.h"
#include "python/src/module.h"
#include "python/src/options.h"
#include "python/src/result_binding.h"

namespace mlndt {
namespace python {
namespace {

// The odometry's own fields (their descriptions:
// odometry/odometry_option_tables.h); the registration's are
// RegistrationOptions keywords beside them (as mlndt_odometry's flags).
const StructBinding<OdometryOptions>& OdometryBinding() {
  static const StructBinding<OdometryOptions> binding(
      OdometryOwnOptionsTable());
  return binding;
}

// The odometry fields of `kwargs` and, in the others, the registration's
// ("preset" and RegistrationOptions fields; grid builds the local map).
OdometryOptions OdometryOptionsFromPython(const py::kwargs& kwargs) {
  const std::vector<std::string> own = OdometryBinding().Names();
  py::dict odometry_fields;
  py::kwargs registration_fields;
  for (const auto& item : kwargs) {
    const std::string key = item.first.cast<std::string>();
    if (std::find(own.begin(), own.end(), key) != own.end()) {
      odometry_fields[item.first] = item.second;
    } else {
      registration_fields[item.first] = item.second;
    }
  }
  if (registration_fields.contains("initial_uncertainty")) {
    ThrowValueError(
        "invalid option: initial_uncertainty does not apply to the "
        "odometry (each scan's comes from its prediction; see prediction=)");
  }
  OdometryOptions options;
  options.registration = RegistrationOptionsFromPython(
      registration_fields, py::none(), false, OdometryRegistrationOptions());
  options.local_map.grid = options.registration.grid;
  OdometryBinding().Update(odometry_fields, "", &options);
  std::string error;
  if (!OdometryBinding().Validate(options, "", &error)) ThrowValueError(error);
  return options;
}

// Per-point times of a scan of `num_points` points, or empty for None.
std::vector<double> PointTimesFromPython(const py::handle times,
                                         size_t num_points,
                                         const std::string& what) {
  if (times.is_none()) return {};
  const auto array =
      py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(
          times);
  if (!array || array.ndim() != 1 ||
      static_cast<size_t>(array.size()) != num_points) {
    ThrowValueError(what + ": expected one time per point (" +
                    std::to_string(num_points) + " floats, seconds after " +
                    "the stamp), got " + DescribeValue(times));
  }
  return std::vector<double>(array.data(), array.data() + array.size());
}

// One Process at a time (the odometry is state); the GIL is released.
class PyOdometry {
 public:
  explicit PyOdometry(const py::kwargs& kwargs)
      : odometry_(OdometryOptionsFromPython(kwargs)) {}

  OdometryResult Process(const py::object& points,
                         double stamp_s,
                         const py::object& point_times) {
    const PointCloud cloud = PointsFromPython(points, "points", false);
    const std::vector<double> times =
        PointTimesFromPython(point_times, cloud.size(), "point_times");
    OdometryResult result;
    std::string error;
    bool ok = false;
    {
      py::gil_scoped_release release;
      const std::lock_guard<std::mutex> lock(mutex_);
      ok = odometry_.Process({stamp_s, &cloud, &times}, &result, &error);
    }
    if (!ok) ThrowValueError("process: " + error);
    return result;
  }

  size_t num_processed() {
    const std::lock_guard<std::mutex> lock(mutex_);
    return odometry_.num_processed();
  }

 private:
  Odometry odometry_;
  std::mutex mutex_;
};

// scans[k] as a cloud: a path is read, an array converted (with the GIL).
bool LoadScan(const py::list& scans,
              const py::list& times,
              size_t k,
              PointCloud* cloud,
              std::vector<double>* point_times) {
  const std::string what = "scans[" + std::to_string(k) + "]";
  py::gil_scoped_acquire acquire;
  const py::object scan = scans[k];
  if (py::isinstance<py::str>(scan) || py::hasattr(scan, "__fspath__")) {
    const std::string path = PathString(scan);
    std::string error;
    bool ok = false;
    {
      py::gil_scoped_release release;
      ok = ReadPointCloud(path, cloud, nullptr, &error);
    }
    if (!ok) ThrowReadError(path, what + ": " + error);
  } else {
    *cloud = PointsFromPython(scan, what.c_str(), false);
  }
  *point_times =
      PointTimesFromPython(times.empty() ? py::none() : py::object(times[k]),
                           cloud->size(),
                           "point_times[" + std::to_string(k) + "]");
  return true;
}

py::list ListOf(const py::object& items, const char* what, size_t n) {
  if (items.is_none()) return py::list();
  py::list list(items);
  if (list.size() != n) {
    ThrowValueError(std::string(what) + ": " + std::to_string(list.size()) +
                    " entries for " + std::to_string(n) + " scans");
  }
  return list;
}

std::vector<OdometryResult> RunOdometryPython(const py::iterable& scan_items,
                                              const py::object& stamps_arg,
                                              const py::object& times_arg,
                                              const py::kwargs& kwargs) {
  const OdometryOptions options = OdometryOptionsFromPython(kwargs);
  const py::list scans(scan_items);
  const size_t n = scans.size();
  if (n < 2) {
    ThrowValueError("scans: odometry needs at least 2 scans, got " +
                    std::to_string(n));
  }
  std::vector<double> stamps(n);
  for (size_t k = 0; k < n; ++k) stamps[k] = static_cast<double>(k);
  const py::list stamp_list = ListOf(stamps_arg, "stamps", n);
  for (size_t k = 0; k < stamp_list.size(); ++k) {
    try {
      stamps[k] = py::cast<double>(stamp_list[k]);
    } catch (const py::cast_error&) {
      throw py::type_error("stamps[" + std::to_string(k) +
                           "]: expected a number of seconds, got " +
                           std::string(py::repr(stamp_list[k])));
    }
  }
  const py::list times = ListOf(times_arg, "point_times", n);
  const OdometryScanLoader load = [&](size_t k,
                                      PointCloud* cloud,
                                      std::vector<double>* point_times,
                                      double* stamp_s,
                                      std::string*) {
    *stamp_s = stamps[k];
    return LoadScan(scans, times, k, cloud, point_times);
  };
  std::vector<OdometryResult> results;
  OdometrySummary summary;
  std::string error;
  bool ok = false;
  {
    py::gil_scoped_release release;
    ok = RunOdometry(options, n, load, {}, &results, &summary, &error);
  }
  if (!ok) ThrowValueError("run_odometry: " + error);
  return results;
}

void DefineResult(py::module_& m) {
  using R = OdometryResult;
  py::class_<R> result(
      m,
      "OdometryResult",
      "One scan of the odometry (mlndt::OdometryResult): the prediction, the "
      "pose (world_from_sensor; the first scan defines the world), the "
      "odometry's verdict, how the local map changed and the registration's "
      "whole result. The properties are the struct's fields "
      "(OdometryResultTable()), named and in the units of the C++ struct; "
      "todict() gives them all, as a scan of mlndt_odometry's scans.json "
      "does.");
  DefineResultProperties(result, OdometryResultTable());
  result
      .def_property_readonly(
          "registration",
          [](const R& r) -> const RegistrationSummary& {
            return r.registration;
          },
          py::return_value_policy::reference_internal,
          "The registration whose result was used: a RegistrationResult "
          "(todict()[\"registration\"] as a dict).")
      .def("__repr__", [](const R& r) {
        return "<mlndt.OdometryResult scan " + std::to_string(r.index) + " " +
               TerminationTypeToString(r.termination_type) +
               (r.fallback ? " (fallback)>" : ">");
      });
}

}  // namespace

void DefineOdometry(py::module_& m) {
  DefineResult(m);
  const std::string options_doc =
      "Options: the odometry's fields below, and RegistrationOptions "
      "fields as for\nmlndt.register (grid= builds the local map; "
      "initial_uncertainty comes from the\nprediction). ValueError "
      "names an invalid one.\n" +
      OdometryBinding().Describe(OdometryOptions(), "    ");
  py::class_<PyOdometry>(
      m,
      "Odometry",
      "Scan-to-local-map LiDAR odometry with ML-NDT (mlndt::Odometry), scan "
      "by scan.")
      .def(py::init<const py::kwargs&>(),
           ("Odometry(**options)\n\n" + options_doc).c_str())
      .def("process",
           &PyOdometry::Process,
           py::arg("points"),
           py::arg("stamp_s"),
           py::arg("point_times") = py::none(),
           "process(points, stamp_s, point_times=None) -> OdometryResult\n\n"
           "The next scan: (N, 3) points in its sensor frame, its stamp [s] "
           "(after the last\none's) and optionally one time per point [s, "
           "relative to the stamp] to deskew it.\nValueError for bad input "
           "(the odometry's state is then unchanged). The GIL is\nreleased.")
      .def_property_readonly("num_processed", &PyOdometry::num_processed);
  m.def("run_odometry",
        &RunOdometryPython,
        py::arg("scans"),
        py::arg("stamps") = py::none(),
        py::arg("point_times") = py::none(),
        ("run_odometry(scans, stamps=None, point_times=None, **options)\n"
         "    -> list[OdometryResult]\n\n"
         "The odometry over a sequence, as mlndt_odometry runs it: scans are "
         "paths (read\none at a time) or (N, 3) arrays; stamps one per scan "
         "[s] (None: the scan\nindices, as mlndt_odometry without --times); "
         "point_times None or one array (or\nNone) per scan. "
         "FileNotFoundError/OSError for a scan that cannot be read,\n"
         "ValueError naming the argument or option otherwise.\n\n" +
         options_doc)
            .c_str());
}

}  // namespace python
}  // namespace mlndt
