#pragma once

// mlndt.register and the RegistrationResult it returns (a
// RegistrationSummary with numpy views of its fields).

#include <pybind11/pybind11.h>

#include <string>

#include "mlndt/cloud/point_cloud.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/registration/registration_options.h"
#include "mlndt/registration/registration_summary.h"

namespace mlndt {
namespace python {

namespace py = pybind11;

// mlndt::Register with the GIL released (the map overload when `map` is not
// null, else the one that builds the map of `reference`).
RegistrationSummary RegisterReleasingGil(const RegistrationOptions& options,
                                         const LayeredGrid* map,
                                         const PointCloud* reference,
                                         const PointCloud& input,
                                         const Isometry3d& initial);

// The docstring part shared by register and LayeredMap.register: the
// arguments after the clouds, the options, the result and the errors.
std::string RegisterArgumentsDoc();

}  // namespace python
}  // namespace mlndt
