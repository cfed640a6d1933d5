#pragma once

// The library's option structs as Python keyword arguments (the scheme is in
// option_binding.h): a top-level RegistrationOptions field is a keyword named
// as the C++ field, a nested struct is a dict of its fields, e.g.
//   mlndt.register(ref, inp, grid={"finest_cell_size_m": 1.0},
//                  backend={"type": "lm"}, num_threads=2)
// and preset="paper" starts from PaperRegistrationOptions() instead of
// RegistrationOptions().

#include <pybind11/pybind11.h>

#include <string>

#include "mlndt/cloud/range_filter.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/registration/registration_options.h"
#include "python/src/option_binding.h"

namespace mlndt {
namespace python {

const StructBinding<RegistrationOptions>& RegistrationOptionsBinding();
const StructBinding<LayeredGridOptions>& LayeredGridOptionsBinding();
const StructBinding<RangeFilterOptions>& RangeFilterOptionsBinding();

// The options of `kwargs` ("preset" and RegistrationOptions fields) and
// `initial_uncertainty` (None, (translation_m, rotation_deg) or a dict of
// InitialGuessUncertainty fields), validated. `map_given`: the map is built
// already, so the grid option is refused (it would be ignored). Raises
// ValueError naming the field. The fields not given keep `defaults`' values
// (preset="paper": PaperRegistrationOptions()'s).
RegistrationOptions RegistrationOptionsFromPython(
    const py::kwargs& kwargs,
    py::handle initial_uncertainty,
    bool map_given,
    const RegistrationOptions& defaults = RegistrationOptions());

// The map options of `kwargs` ("preset" and LayeredGridOptions fields),
// validated.
LayeredGridOptions LayeredGridOptionsFromPython(const py::kwargs& kwargs);

// The range filter of `kwargs` (RangeFilterOptions fields), validated.
RangeFilterOptions RangeFilterOptionsFromPython(const py::kwargs& kwargs);

// Docstring sections listing every field with its type and default.
std::string RegistrationOptionsDoc();
std::string LayeredGridOptionsDoc();
std::string RangeFilterOptionsDoc();

// mlndt.default_options(preset="default").
void DefineOptions(py::module_& m);

}  // namespace python
}  // namespace mlndt
