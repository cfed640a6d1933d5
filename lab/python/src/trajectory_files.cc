// mlndt_lab.read_trajectory and write_trajectory: KITTI and TUM pose files
// (lab/eval/trajectory_io.h), the files mlndt_eval reads.

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <string>
#include <vector>

#include "lab/eval/trajectory_io.h"
#include "lab/python/src/lab_module.h"
#include "python/src/errors.h"
#include "python/src/module.h"

namespace mlndt {
namespace python {
namespace {

TrajectoryFormat ParseFormat(const std::string& value) {
  TrajectoryFormat format;
  if (!StringToTrajectoryFormat(value, &format)) {
    throw py::value_error("format = '" + value + "': expected kitti or tum");
  }
  return format;
}

py::dict ReadTrajectoryFile(const py::object& path_like,
                            const std::string& format) {
  const std::string path = PathString(path_like);
  Trajectory trajectory;
  TrajectoryFormat detected = TrajectoryFormat::KITTI;
  std::string error;
  bool ok = false;
  if (format == "auto") {
    ok = DetectTrajectoryFormat(path, &detected, &error) &&
         ReadTrajectory(path, detected, &trajectory, &error);
  } else {
    detected = ParseFormat(format);
    ok = ReadTrajectory(path, detected, &trajectory, &error);
  }
  if (!ok) ThrowReadError(path, error);
  py::dict d;
  d["format"] = TrajectoryFormatToString(detected);
  d["timestamps"] = py::array(py::cast(trajectory.timestamps_s()));
  d["poses"] = PosesToPython(trajectory.poses());
  return d;
}

void WriteTrajectoryFile(const py::object& path_like,
                         const py::object& poses,
                         const py::object& timestamps,
                         const std::string& format) {
  const std::string path = PathString(path_like);
  const std::vector<Isometry3d> list = PosesFromPython(poses, "poses");
  Trajectory trajectory(list);
  if (!timestamps.is_none()) {
    const auto times = timestamps.cast<std::vector<double>>();
    if (times.size() != list.size()) {
      throw py::value_error("timestamps: " + std::to_string(times.size()) +
                            " for " + std::to_string(list.size()) + " poses");
    }
    trajectory = Trajectory();
    for (size_t k = 0; k < list.size(); ++k) {
      if (!std::isfinite(times[k]) || (k > 0 && !(times[k] > times[k - 1]))) {
        throw py::value_error("timestamps[" + std::to_string(k) +
                              "]: must be finite and increase strictly");
      }
      trajectory.Add(times[k], list[k]);
    }
  }
  std::string error;
  if (!WriteTrajectory(path, ParseFormat(format), trajectory, &error)) {
    ThrowWriteError(path, error);
  }
}

}  // namespace

void DefineTrajectoryFiles(py::module_& m) {
  m.def("read_trajectory",
        &ReadTrajectoryFile,
        py::arg("path"),
        py::arg("format") = "auto",
        "read_trajectory(path, format=\"auto\") -> dict\n\n"
        "Reads a KITTI (12 numbers a line) or TUM (t tx ty tz qx qy qz qw) "
        "pose file;\n\"auto\" detects the format as mlndt_eval does. "
        "Returns format, timestamps (N,)\n(KITTI: 0, 1, 2, ...) and poses "
        "(N, 4, 4) world_from_sensor. FileNotFoundError\nfor a missing "
        "file, OSError naming the line for a bad one.");
  m.def("write_trajectory",
        &WriteTrajectoryFile,
        py::arg("path"),
        py::arg("poses"),
        py::arg("timestamps") = py::none(),
        py::arg("format") = "kitti",
        "write_trajectory(path, poses, timestamps=None, format=\"kitti\") "
        "-> None\n\n"
        "Writes poses (N, 4, 4) as KITTI or TUM lines with 17 significant "
        "digits (atomic);\ntimestamps None: 0, 1, 2, ... Raises ValueError "
        "for bad poses or timestamps,\nOSError when the file cannot be "
        "written.");
}

}  // namespace python
}  // namespace mlndt
