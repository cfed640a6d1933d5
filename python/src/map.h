#pragma once

// mlndt.LayeredMap: a layered NDT map (grid/layered_grid.h) held by a
// shared_ptr, so that a registration or a Localizer running with the GIL
// released keeps it alive (localizer.cc uses grid_ptr()).

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>

#include <memory>
#include <string>

#include "mlndt/grid/layered_grid.h"

namespace mlndt {
namespace python {

namespace py = pybind11;

class LayeredMap {
 public:
  explicit LayeredMap(std::shared_ptr<const LayeredGrid> grid)
      : grid_(std::move(grid)) {}

  static LayeredMap Build(const py::object& points,
                          int num_threads,
                          double max_memory_gb,
                          const py::kwargs& kwargs);
  static LayeredMap Load(const py::object& path_like);
  void Save(const py::object& path_like) const;

  py::object Register(const py::object& input,
                      const py::object& initial,
                      const py::object& initial_uncertainty,
                      const py::kwargs& kwargs) const;

  py::list Layers() const;
  Eigen::Matrix<double, 2, 3> Bounds() const;
  // The occupied cells of layer i (1-based): means, covariances, counts.
  py::dict Cells(int i) const;
  std::string Repr() const;

  const LayeredGrid& grid() const { return *grid_; }
  const std::shared_ptr<const LayeredGrid>& grid_ptr() const { return grid_; }

 private:
  std::shared_ptr<const LayeredGrid> grid_;
};

}  // namespace python
}  // namespace mlndt
