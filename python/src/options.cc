#include "python/src/options.h"

// The bindings read the library's option tables (option_table.h): a field
// added to a struct's table is a Python keyword, with its doc, here with no
// change (and one line in python/mlndt/__init__.pyi; python/tests/
// test_stubs.py checks the stub).

namespace mlndt {
namespace python {
namespace {

const StructBinding<InitialGuessUncertainty>& InitialGuessUncertaintyBinding() {
  static const StructBinding<InitialGuessUncertainty> binding(
      InitialGuessUncertaintyTable());
  return binding;
}

// Pops "preset" from `kwargs` (default "default").
std::string PopPreset(py::dict* kwargs) {
  if (!kwargs->contains("preset")) return "default";
  const py::object value = (*kwargs)["preset"];
  PyDict_DelItemString(kwargs->ptr(), "preset");
  if (!py::isinstance<py::str>(value)) {
    ThrowValueError("invalid option: preset = " + DescribeValue(value) +
                    "; expected \"default\" or \"paper\"");
  }
  const std::string preset = value.cast<std::string>();
  if (preset != "default" && preset != "paper") {
    ThrowValueError("invalid option: preset = '" + preset +
                    "'; expected \"default\" or \"paper\"");
  }
  return preset;
}

template <typename S>
void ValidateOrThrow(const StructBinding<S>& binding, const S& options) {
  std::string error;
  if (!binding.Validate(options, "", &error)) ThrowValueError(error);
}

}  // namespace

const StructBinding<RangeFilterOptions>& RangeFilterOptionsBinding() {
  static const StructBinding<RangeFilterOptions> binding(
      RangeFilterOptionsTable());
  return binding;
}

const StructBinding<LayeredGridOptions>& LayeredGridOptionsBinding() {
  static const StructBinding<LayeredGridOptions> binding(
      LayeredGridOptionsTable());
  return binding;
}

const StructBinding<RegistrationOptions>& RegistrationOptionsBinding() {
  static const StructBinding<RegistrationOptions> binding(
      RegistrationOptionsTable());
  return binding;
}

RegistrationOptions RegistrationOptionsFromPython(
    const py::kwargs& kwargs,
    py::handle initial_uncertainty,
    bool map_given,
    const RegistrationOptions& defaults) {
  py::dict options = py::dict(kwargs);  // A copy: "preset" is popped.
  const std::string preset = PopPreset(&options);
  RegistrationOptions result =
      preset == "paper" ? PaperRegistrationOptions() : defaults;
  if (map_given && options.contains("grid")) {
    ThrowValueError(
        "invalid option: grid does not apply to LayeredMap.register (the map "
        "is built already; give grid options to LayeredMap.build)");
  }
  RegistrationOptionsBinding().Update(options, "", &result);
  if (!initial_uncertainty.is_none()) {
    InitialGuessUncertainty& u = result.initial_uncertainty;
    if (py::isinstance<py::dict>(initial_uncertainty)) {
      InitialGuessUncertaintyBinding().Update(
          initial_uncertainty, "initial_uncertainty.", &u);
    } else {
      std::vector<double> pair;
      if (!OptionCodec<std::vector<double>>::FromPython(initial_uncertainty,
                                                        &pair) ||
          pair.size() != 2) {
        ThrowValueError("invalid option: initial_uncertainty = " +
                        DescribeValue(initial_uncertainty) +
                        "; expected (translation_m, rotation_deg), a dict "
                        "of InitialGuessUncertainty fields, or None");
      }
      u.given = true;
      u.translation_m = pair[0];
      u.rotation_deg = pair[1];
    }
  }
  ValidateOrThrow(RegistrationOptionsBinding(), result);
  return result;
}

LayeredGridOptions LayeredGridOptionsFromPython(const py::kwargs& kwargs) {
  py::dict options = py::dict(kwargs);
  const std::string preset = PopPreset(&options);
  LayeredGridOptions result =
      preset == "paper" ? PaperLayeredGridOptions() : LayeredGridOptions();
  LayeredGridOptionsBinding().Update(options, "", &result);
  ValidateOrThrow(LayeredGridOptionsBinding(), result);
  return result;
}

RangeFilterOptions RangeFilterOptionsFromPython(const py::kwargs& kwargs) {
  RangeFilterOptions result;
  RangeFilterOptionsBinding().Update(kwargs, "", &result);
  ValidateOrThrow(RangeFilterOptionsBinding(), result);
  return result;
}

std::string RegistrationOptionsDoc() {
  return RegistrationOptionsBinding().Describe(RegistrationOptions(), "    ");
}

std::string LayeredGridOptionsDoc() {
  return LayeredGridOptionsBinding().Describe(LayeredGridOptions(), "    ");
}

std::string RangeFilterOptionsDoc() {
  return RangeFilterOptionsBinding().Describe(RangeFilterOptions(), "    ");
}

void DefineOptions(py::module_& m) {
  m.def(
      "default_options",
      [](const std::string& preset) {
        if (preset == "default") {
          return RegistrationOptionsBinding().ToDict(RegistrationOptions());
        }
        if (preset == "paper") {
          return RegistrationOptionsBinding().ToDict(
              PaperRegistrationOptions());
        }
        ThrowValueError("invalid option: preset = '" + preset +
                        "'; expected \"default\" or \"paper\"");
      },
      py::arg("preset") = "default",
      "default_options(preset=\"default\") -> dict\n\n"
      "Every registration option with its value, nested structs as dicts "
      "and enums as their C++ names: RegistrationOptions() for \"default\", "
      "PaperRegistrationOptions() for \"paper\". The dict can be edited and "
      "passed back, e.g. mlndt.register(ref, inp, **options) (its "
      "initial_uncertainty entry then goes to the initial_uncertainty "
      "argument).");
  m.def(
      "resolve_options",
      [](const py::object& initial_uncertainty, const py::kwargs& kwargs) {
        return RegistrationOptionsBinding().ToDict(
            RegistrationOptionsFromPython(kwargs, initial_uncertainty, false));
      },
      py::arg("initial_uncertainty") = py::none(),
      "resolve_options(initial_uncertainty=None, **options) -> dict\n\n"
      "The options mlndt.register would use for these arguments: the "
      "preset with the given\nfields replaced, checked by the library's "
      "IsValid, as default_options() lays them\nout. Raises ValueError "
      "naming an unknown or invalid field, as register does\n(without "
      "reading any cloud): check options before sending work elsewhere.");
}

}  // namespace python
}  // namespace mlndt
