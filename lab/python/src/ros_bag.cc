// mlndt_lab.RosBag and mlndt_lab.BagScan: the sensor_msgs/PointCloud2
// messages of one topic of a ROS 1 bag (lab/io/ros_bag_scans.h), with their
// header stamps and per-point times, as mlndt_odometry --bag reads them.

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <memory>
#include <mutex>
#include <string>

#include "lab/io/ros_bag_scans.h"
#include "lab/python/src/lab_module.h"
#include "python/src/arrays.h"
#include "python/src/errors.h"
#include "python/src/module.h"

namespace mlndt {
namespace python {
namespace {

// The reader and the lock that serialises its reads (one bag handle).
struct PyRosBag {
  std::unique_ptr<RosBagScans> bag;
  std::mutex mutex;
};

std::shared_ptr<PyRosBag> OpenBag(const py::object& path_arg,
                                  const std::string& topic) {
  const std::string path = PathString(path_arg);
  if (!RosBagSupported()) {
    throw py::value_error(
        "this mlndt was built without ROS 1 bag support "
        "(MLNDT_WITH_ROSBAG=OFF; scripts/install_deps.sh installs "
        "librosbag-storage-dev and libsensor-msgs-dev)");
  }
  if (!std::filesystem::is_regular_file(path)) {
    ThrowReadError(path, "path: " + path + ": no such file");
  }
  auto result = std::make_shared<PyRosBag>();
  std::string error;
  bool ok = false;
  {
    py::gil_scoped_release release;
    ok = RosBagScans::Open(path, topic, &result->bag, &error);
  }
  if (!ok) throw py::value_error(error);
  return result;
}

BagScan ReadScan(PyRosBag& b, long index) {
  const long n = static_cast<long>(b.bag->size());
  if (index < 0) index += n;
  if (index < 0 || index >= n) {
    throw py::index_error("message " + std::to_string(index) + " of a topic " +
                          "with " + std::to_string(n) + " messages");
  }
  BagScan scan;
  std::string error;
  bool ok = false;
  {
    py::gil_scoped_release release;
    const std::lock_guard<std::mutex> lock(b.mutex);
    ok = b.bag->Read(static_cast<size_t>(index), &scan, &error);
  }
  if (!ok) throw py::value_error(error);
  return scan;
}

void DefineBagScan(py::module_& m) {
  py::class_<BagScan>(m,
                      "BagScan",
                      "One PointCloud2 message (lab BagScan): its header "
                      "stamp, frame, finite\npoints in the sensor frame and "
                      "per-point times.")
      .def_readonly("stamp_s", &BagScan::stamp_s, "header.stamp [s].")
      .def_readonly("frame_id", &BagScan::frame_id)
      .def_property_readonly(
          "points",
          [](const BagScan& s) { return PointsToPython(s.cloud); },
          "(N, 3) float64, the finite points (the message's x, y, z).")
      .def_property_readonly(
          "point_times",
          [](const BagScan& s) -> py::object {
            if (s.time_field.empty()) return py::none();
            return py::array_t<double>(
                static_cast<py::ssize_t>(s.point_times_s.size()),
                s.point_times_s.data());
          },
          "(N,) float64 times relative to stamp_s [s], or None when the "
          "message has no\ntime field.")
      .def_readonly("time_field",
                    &BagScan::time_field,
                    "The field the times came from (time, t, offset_time, "
                    "timestamp), or \"\".")
      .def("__repr__", [](const BagScan& s) {
        return "<mlndt_lab.BagScan " + std::to_string(s.cloud.size()) +
               " points at " + std::to_string(s.stamp_s) + " s>";
      });
}

}  // namespace

void DefineRosBag(py::module_& m) {
  DefineBagScan(m);
  m.def("rosbag_supported",
        &RosBagSupported,
        "rosbag_supported() -> bool\n\nWhether this build reads ROS 1 bags "
        "(MLNDT_WITH_ROSBAG).");
  py::class_<PyRosBag, std::shared_ptr<PyRosBag>>(
      m,
      "RosBag",
      "The sensor_msgs/PointCloud2 messages of one topic of a ROS 1 bag "
      "(lab RosBagScans),\nin bag order; a sequence of BagScan.")
      .def(py::init(&OpenBag),
           py::arg("path"),
           py::arg("topic"),
           "RosBag(path, topic)\n\nFileNotFoundError for a missing file; "
           "ValueError naming the file for one that\nis not a bag, and "
           "the bag's point-cloud topics when `topic` is missing or of\n"
           "another type; ValueError when this build reads no bags.")
      .def("__len__", [](PyRosBag& b) { return b.bag->size(); })
      .def("__getitem__",
           &ReadScan,
           py::arg("index"),
           "bag[i] -> BagScan (read on each call). IndexError past the "
           "end; ValueError for a\nmalformed message.")
      .def_property_readonly("path", [](PyRosBag& b) { return b.bag->path(); })
      .def_property_readonly("topic",
                             [](PyRosBag& b) { return b.bag->topic(); });
}

}  // namespace python
}  // namespace mlndt
