// mlndt.read_cloud, write_cloud and filter_range: the library's readers,
// writers (cloud/io.h) and range filter (cloud/range_filter.h).

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>

#include "mlndt/cloud/cloud_format.h"
#include "mlndt/cloud/io.h"
#include "mlndt/cloud/range_filter.h"
#include "python/src/arrays.h"
#include "python/src/errors.h"
#include "python/src/module.h"
#include "python/src/options.h"

namespace mlndt {
namespace python {
namespace {

// The extension decides the format; an unknown one (or, for writing, one
// the library does not write: io.h writes PCD and PLY) is a bad argument.
void CheckFormat(const std::string& path, bool writing) {
  CloudFormat format;
  std::string error;
  if (!CloudFormatFromPath(path, &format, &error)) {
    throw py::value_error(error);
  }
  if (writing && format != CloudFormat::PCD && format != CloudFormat::PLY) {
    throw py::value_error(path + ": writing " + CloudFormatToString(format) +
                          " is not supported (write .pcd or .ply)");
  }
}

py::array_t<double> ReadCloud(const py::object& path_like) {
  const std::string path = PathString(path_like);
  CheckFormat(path, false);
  PointCloud cloud;
  std::string error;
  bool ok = false;
  {
    py::gil_scoped_release release;
    ok = ReadPointCloud(path, &cloud, nullptr, &error);
  }
  if (!ok) ThrowReadError(path, error);
  return PointsToPython(std::move(cloud));
}

void WriteCloud(const py::object& path_like, const py::object& points) {
  const std::string path = PathString(path_like);
  CheckFormat(path, true);
  const PointCloud cloud = PointsFromPython(points, "points", true);
  std::string error;
  bool ok = false;
  {
    py::gil_scoped_release release;
    ok = WritePointCloud(path, cloud, &error);
  }
  if (!ok) ThrowWriteError(path, error);
}

py::array_t<double> FilterRange(const py::object& points,
                                const py::kwargs& options) {
  const RangeFilterOptions filter = RangeFilterOptionsFromPython(options);
  const PointCloud cloud = PointsFromPython(points, "points", true);
  return PointsToPython(FilterByRange(filter, cloud, nullptr));
}

}  // namespace

void DefineCloud(py::module_& m) {
  m.def("read_cloud",
        &ReadCloud,
        py::arg("path"),
        "read_cloud(path) -> numpy.ndarray\n\n"
        "Reads a point cloud file with the library's readers, chosen by the "
        "extension: .pcd (ascii, binary, binary_compressed), .ply (ascii, "
        "binary), .bin (KITTI Velodyne), .3d (3DTK, converted to metres and "
        "a right-handed frame), .xyz/.txt. Returns an (N, 3) float64 array "
        "of x, y, z in metres (points with a non-finite coordinate are "
        "dropped by the reader). The array owns the points read (no copy).\n\n"
        "Raises ValueError for an unknown extension, FileNotFoundError for a "
        "missing file and OSError for a file the reader refuses (truncated, "
        "corrupt, unsupported fields), with the library's message.");
  m.def("write_cloud",
        &WriteCloud,
        py::arg("path"),
        py::arg("points"),
        "write_cloud(path, points) -> None\n\n"
        "Writes an (N, 3) array as .pcd (binary) or .ply (binary little "
        "endian), float32 x y z (about 7 significant digits survive), "
        "atomically (a temporary file renamed onto path).\n\n"
        "Raises ValueError for another extension, a wrong shape or a "
        "non-finite row, OSError (FileNotFoundError for a missing folder) "
        "when the file cannot be written.");
  m.def("filter_range",
        &FilterRange,
        py::arg("points"),
        ("filter_range(points, **range_filter) -> numpy.ndarray\n\n"
         "The points the library's range filter keeps, in input order: what "
         "register() drops from a scan in its sensor frame (returns at the "
         "sensor, a saturated maximum range) before it builds a map of it "
         "or samples it. Options, RangeFilterOptions fields:\n" +
         RangeFilterOptionsDoc())
            .c_str());
}

}  // namespace python
}  // namespace mlndt
