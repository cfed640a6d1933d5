// mlndt.LayeredMap: a layered NDT map built once (grid/layered_grid.h),
// saved and loaded (grid/grid_io.h), and registered against, from any
// number of threads (the map is immutable once built).

#include "python/src/map.h"

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <memory>
#include <sstream>

#include "mlndt/grid/grid_io.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/pipeline/map_builder.h"
#include "python/src/arrays.h"
#include "python/src/errors.h"
#include "python/src/module.h"
#include "python/src/options.h"
#include "python/src/registration.h"

namespace mlndt {
namespace python {

LayeredMap LayeredMap::Build(const py::object& points,
                             int num_threads,
                             double max_memory_gb,
                             const py::kwargs& kwargs) {
  const LayeredGridOptions options = LayeredGridOptionsFromPython(kwargs);
  if (num_threads < 1 || num_threads > 256) {
    throw py::value_error(
        "invalid option: num_threads = " + std::to_string(num_threads) +
        "; it must be in [1, 256]");
  }
  if (!(max_memory_gb >= 0.0 && max_memory_gb <= 1e6)) {
    throw py::value_error(
        "invalid option: max_memory_gb = " + std::to_string(max_memory_gb) +
        "; it must be in [0, 1e6] (0 = no limit)");
  }
  // The library's map build from one cloud (pipeline/map_builder.h), as
  // mlndt_map builds: the memory estimated before anything large is
  // allocated, the map refused when it cannot be used (0 occupied cells,
  // coordinates beyond 1e8 m); no range or voxel filter.
  MapBuildOptions build;
  build.grid = options;
  build.max_memory_bytes = static_cast<size_t>(max_memory_gb * 1e9);
  build.num_threads = num_threads;
  PointCloud cloud = PointsFromPython(points, "points", false);
  auto grid = std::make_shared<LayeredGrid>();
  MapBuildSummary summary;
  std::string error;
  bool ok = false;
  {
    py::gil_scoped_release release;
    ok = BuildMapFromCloud(
        build, std::move(cloud), grid.get(), &summary, &error);
  }
  if (!ok && summary.memory.exceeds_limit) {
    PyErr_SetString(
        PyExc_MemoryError,
        ("LayeredMap.build: " + error + " (max_memory_gb; 0 = no limit)")
            .c_str());
    throw py::error_already_set();
  }
  if (!ok) throw py::value_error("LayeredMap.build: " + error);
  return LayeredMap(std::move(grid));
}

LayeredMap LayeredMap::Load(const py::object& path_like) {
  const std::string path = PathString(path_like);
  auto grid = std::make_shared<LayeredGrid>();
  std::string error;
  bool ok = false;
  {
    py::gil_scoped_release release;
    ok = LoadLayeredGrid(path, grid.get(), &error);
  }
  if (!ok) ThrowReadError(path, error);
  return LayeredMap(std::move(grid));
}

void LayeredMap::Save(const py::object& path_like) const {
  const std::string path = PathString(path_like);
  std::string error;
  bool ok = false;
  {
    py::gil_scoped_release release;
    ok = SaveLayeredGrid(path, *grid_, &error);
  }
  if (!ok) ThrowWriteError(path, error);
}

py::object LayeredMap::Register(const py::object& input,
                                const py::object& initial,
                                const py::object& initial_uncertainty,
                                const py::kwargs& kwargs) const {
  const RegistrationOptions options =
      RegistrationOptionsFromPython(kwargs, initial_uncertainty, true);
  const Isometry3d guess = TransformFromPython(initial, "initial");
  const PointCloud input_cloud = PointsFromPython(input, "input", false);
  // The shared_ptr copy keeps the map alive while the GIL is released.
  const std::shared_ptr<const LayeredGrid> grid = grid_;
  return py::cast(
      RegisterReleasingGil(options, grid.get(), nullptr, input_cloud, guess));
}

py::list LayeredMap::Layers() const {
  py::list layers;
  for (const LayerInfo& info : grid_->layer_info()) {
    py::dict layer;
    layer["layer"] = info.layer;
    layer["cell_size_m"] = info.cell_size_m;
    layer["dims"] = py::make_tuple(info.dims.x(), info.dims.y(), info.dims.z());
    layer["occupied_cells"] = info.occupied_cells;
    layer["sparse_cells"] = info.sparse_cells;
    layer["degenerate_cells"] = info.degenerate_cells;
    layers.append(std::move(layer));
  }
  return layers;
}

Eigen::Matrix<double, 2, 3> LayeredMap::Bounds() const {
  Eigen::Matrix<double, 2, 3> bounds;
  bounds.row(0) = grid_->bounds().min().transpose();
  bounds.row(1) = grid_->bounds().max().transpose();
  return bounds;
}

py::dict LayeredMap::Cells(int i) const {
  if (i < 1 || i > grid_->num_layers()) {
    throw py::index_error("layer " + std::to_string(i) +
                          " of a map with layers 1.." +
                          std::to_string(grid_->num_layers()));
  }
  const std::vector<NdtCell>& cells = grid_->layer(i).cells();
  const py::ssize_t n = static_cast<py::ssize_t>(cells.size());
  py::array_t<double> means({n, py::ssize_t{3}});
  py::array_t<double> covariances({n, py::ssize_t{3}, py::ssize_t{3}});
  py::array_t<int64_t> counts(n);
  auto mean = means.mutable_unchecked<2>();
  auto covariance = covariances.mutable_unchecked<3>();
  auto count = counts.mutable_unchecked<1>();
  for (py::ssize_t k = 0; k < n; ++k) {
    const NdtCell& cell = cells[static_cast<size_t>(k)];
    count(k) = cell.count;
    for (int a = 0; a < 3; ++a) {
      mean(k, a) = cell.mean(a);
      for (int b = 0; b < 3; ++b) covariance(k, a, b) = cell.covariance(a, b);
    }
  }
  py::dict result;
  result["means"] = means;
  result["covariances"] = covariances;
  result["counts"] = counts;
  return result;
}

std::string LayeredMap::Repr() const {
  std::ostringstream out;
  out << "<mlndt.LayeredMap " << grid_->num_layers() << " layers, cells";
  for (const LayerInfo& info : grid_->layer_info()) {
    out << " " << info.cell_size_m << "m:" << info.occupied_cells;
  }
  out << ", " << grid_->num_points() << " points, " << grid_->MemoryBytes()
      << " bytes>";
  return out.str();
}

namespace {

// Building, loading, saving and registering.
void DefineMapCalls(py::class_<LayeredMap>& map_class) {
  map_class
      .def_static(
          "build",
          &LayeredMap::Build,
          py::arg("points"),
          py::arg("num_threads") = 1,
          py::arg("max_memory_gb") = 8.0,
          ("build(points, num_threads=1, max_memory_gb=8.0, **grid_options) "
           "-> LayeredMap\n\n"
           "Builds the map of an (N, 3) array (LayeredGrid::Build; the GIL "
           "is released).\n"
           "max_memory_gb: the build's memory is estimated first "
           "(mlndt_map's --max_memory_gb);\nover it, MemoryError names what "
           "it needs, before anything large is allocated\n(0 = no limit).\n"
           "No range filter: register(reference, input) also drops the "
           "reference's\nreturns at the sensor first; for the same map "
           "build from filter_range(points).\n"
           "num_threads: OpenMP threads of the build (the map is identical "
           "for every value).\n"
           "preset: \"default\" (LayeredGridOptions()) or \"paper\" "
           "(PaperLayeredGridOptions()).\n"
           "Options, LayeredGridOptions fields (nested ones as dicts):\n" +
           LayeredGridOptionsDoc() +
           "Raises ValueError for invalid options or data, and when the "
           "library refuses the\ncloud (all points coincide, too many "
           "cells) or the map could not be used\n(CheckMapUsable: a layer "
           "with 0 occupied cells, coordinates beyond 1e8 m).")
              .c_str())
      .def_static("load",
                  &LayeredMap::Load,
                  py::arg("path"),
                  "load(path) -> LayeredMap\n\n"
                  "Reads a map file written by save() (or mlndt_map). Raises "
                  "FileNotFoundError\nfor a missing file, OSError for a "
                  "truncated, corrupt or foreign one.")
      .def("save",
           &LayeredMap::Save,
           py::arg("path"),
           "save(path) -> None\n\n"
           "Writes the map file (binary, versioned, checksummed; atomic). "
           "Raises OSError.")
      .def("register",
           &LayeredMap::Register,
           py::arg("input"),
           py::arg("initial") = py::none(),
           py::arg("initial_uncertainty") = py::none(),
           ("register(input, initial=None, initial_uncertainty=None, "
            "**options) -> RegistrationResult\n\n"
            "Registers the input scan onto this map (mlndt::Register with a "
            "map; the grid\noption does not apply and is refused).\n"
            "\n"
            "input: (N, 3) array of x, y, z [m], float64 or float32, any "
            "strides.\n" +
            RegisterArgumentsDoc())
               .c_str());
}

// What a map holds: layers, memory, bounds, options, cells.
void DefineMapContents(py::class_<LayeredMap>& map_class) {
  map_class
      .def_property_readonly(
          "layers",
          &LayeredMap::Layers,
          "One dict per layer, coarsest first: layer (1-based), cell_size_m, "
          "dims (cells\nper axis), occupied_cells, sparse_cells, "
          "degenerate_cells.")
      .def_property_readonly(
          "num_layers",
          [](const LayeredMap& map) { return map.grid().num_layers(); })
      .def_property_readonly(
          "bytes",
          [](const LayeredMap& map) { return map.grid().MemoryBytes(); },
          "Memory the map holds (LayeredGrid::MemoryBytes).")
      .def_property_readonly(
          "bounds",
          &LayeredMap::Bounds,
          "2x3 array: the reference's bounding box, min row then max row "
          "[m].")
      .def_property_readonly(
          "num_points",
          [](const LayeredMap& map) { return map.grid().num_points(); },
          "Points the map was built from.")
      .def_property_readonly(
          "options",
          [](const LayeredMap& map) {
            return LayeredGridOptionsBinding().ToDict(map.grid().options());
          },
          "The LayeredGridOptions it was built with, as a dict.")
      .def("cells",
           &LayeredMap::Cells,
           py::arg("layer"),
           "cells(layer) -> dict\n\n"
           "The occupied cells of a layer (1-based, 1 = coarsest): "
           "\"means\" (k, 3),\n\"covariances\" (k, 3, 3, regularised) [m, "
           "m^2] and \"counts\" (k,).")
      .def("__repr__", &LayeredMap::Repr);
}

}  // namespace

void DefineMap(py::module_& m) {
  py::class_<LayeredMap> map_class(
      m,
      "LayeredMap",
      "A layered NDT map of a reference cloud (mlndt::LayeredGrid): built "
      "once,\nsaved, loaded and registered against (localisation against a "
      "prebuilt map).\nImmutable: any number of threads may register "
      "against one map.");
  DefineMapCalls(map_class);
  DefineMapContents(map_class);
}

}  // namespace python
}  // namespace mlndt
