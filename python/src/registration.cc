#include "python/src/registration.h"

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <utility>

#include "mlndt/registration/registration.h"
#include "python/src/arrays.h"
#include "python/src/module.h"
#include "python/src/options.h"

namespace mlndt {
namespace python {
namespace {

using Summary = RegistrationSummary;

py::dict QualityDict(const Summary& s) {
  py::dict quality;
  quality["points"] = s.quality.points;
  quality["own_cell_fraction"] = s.quality.own_cell_fraction;
  quality["inlier_fraction"] = s.quality.inlier_fraction;
  quality["mean_score"] = s.quality.mean_score;
  quality["median_distance"] = s.quality.median_distance;
  quality["constraint_ratio"] = s.constraints.constraint_ratio;
  quality["flatness"] = s.constraints.flatness;
  quality["probe_evidence"] = s.constraints.probe_evidence;
  return quality;
}

py::list TraceList(const Summary& s) {
  py::list trace;
  for (const IterationRecord& r : s.trace) {
    py::dict record;
    record["iteration"] = r.iteration;
    record["layer"] = r.layer;
    record["score"] = r.score;
    record["step_norm"] = r.step_norm;
    record["step_is_successful"] = r.step_is_successful;
    record["reference_from_input_xi"] = Vector6d(r.reference_from_input_xi);
    record["time_s"] = r.time_s;
    trace.append(std::move(record));
  }
  return trace;
}

Eigen::MatrixXd DegenerateDirections(const Summary& s) {
  const auto& directions = s.constraints.degenerate_directions;
  Eigen::MatrixXd rows(static_cast<Eigen::Index>(directions.size()), 6);
  for (size_t i = 0; i < directions.size(); ++i) {
    rows.row(static_cast<Eigen::Index>(i)) = directions[i].transpose();
  }
  return rows;
}

py::object Register(const py::object& reference,
                    const py::object& input,
                    const py::object& initial,
                    const py::object& initial_uncertainty,
                    const py::kwargs& kwargs) {
  const RegistrationOptions options =
      RegistrationOptionsFromPython(kwargs, initial_uncertainty, false);
  const Isometry3d guess = TransformFromPython(initial, "initial");
  const PointCloud reference_cloud =
      PointsFromPython(reference, "reference", false);
  const PointCloud input_cloud = PointsFromPython(input, "input", false);
  return py::cast(RegisterReleasingGil(
      options, nullptr, &reference_cloud, input_cloud, guess));
}

// The pose and the verdict.
void DefinePoseAndVerdict(py::class_<Summary>& result) {
  result
      .def_property_readonly(
          "reference_from_input",
          [](const Summary& s) {
            return Eigen::Matrix4d(s.reference_from_input.matrix());
          },
          "4x4 transform mapping input points into the reference frame.")
      .def_property_readonly(
          "reference_from_input_xi",
          [](const Summary& s) { return Vector6d(s.reference_from_input_xi); },
          "The same as the pose vector (tx, ty, tz, alpha, beta, gamma) of "
          "Eq. 11, metres and radians.")
      .def_property_readonly(
          "initial_reference_from_input_xi",
          [](const Summary& s) {
            return Vector6d(s.initial_reference_from_input_xi);
          },
          "The initial guess as a pose vector (m, rad).")
      .def_property_readonly(
          "termination",
          [](const Summary& s) {
            return std::string(TerminationTypeToString(s.termination_type));
          },
          "CONVERGENCE, NO_CONVERGENCE, FAILURE, LOW_QUALITY or DEGENERATE "
          "(TerminationTypeToString).")
      .def_property_readonly(
          "converged",
          [](const Summary& s) {
            return s.termination_type == TerminationType::CONVERGENCE;
          },
          "termination == \"CONVERGENCE\".")
      .def_property_readonly(
          "usable",
          &Summary::IsSolutionUsable,
          "CONVERGENCE or NO_CONVERGENCE: the pose passed the quality check "
          "(IsSolutionUsable).")
      .def_readonly("message", &Summary::message, "Why it ended.")
      .def_readonly("algorithm", &Summary::algorithm, "\"ML-NDT\".");
}

// The evidence: fit, degenerate directions, covariance, scores, iterations.
void DefineEvidence(py::class_<Summary>& result) {
  result
      .def_property_readonly(
          "quality",
          &QualityDict,
          "The fit at the solution on the last layer (FitQuality: points, "
          "own_cell_fraction, inlier_fraction, mean_score, median_distance) "
          "and the Hessian's constraint_ratio: the evidence of the verdict.")
      .def_property_readonly(
          "degenerate_directions",
          &DegenerateDirections,
          "(k, 6) unit directions of the pose vector (angles scaled by the "
          "points' RMS range) that the fit does not constrain.")
      .def_property_readonly(
          "covariance",
          [](const Summary& s) { return Matrix6d(s.covariance); },
          "6x6 covariance of the pose vector (tx, ty, tz, alpha, beta, "
          "gamma) of Eq. 11, in m and rad (2 H^-1); inf along degenerate "
          "directions, zero when H is singular.")
      .def_property_readonly(
          "hessian",
          [](const Summary& s) { return Matrix6d(s.hessian); },
          "6x6 Gauss-Newton Hessian of the final score w.r.t. the pose "
          "vector.")
      .def_readonly("score",
                    &Summary::final_score,
                    "Eq. 10 on the last layer at the solution.")
      .def_readonly("initial_score",
                    &Summary::initial_score,
                    "Eq. 10 on the last layer at the initial guess.")
      .def_readonly("iterations",
                    &Summary::num_iterations,
                    "Iterations of the reported solution (len(trace)).")
      .def_readonly("iterations_per_layer",
                    &Summary::iterations_per_layer,
                    "Iterations on each layer, index i - 1 for layer i.")
      .def_readonly("attempts",
                    &Summary::attempts,
                    "Schedule runs (retries and guess comparisons included).");
}

// Layers, point counts, timings and the reports.
void DefineCountsAndReports(py::class_<Summary>& result) {
  result.def_readonly("start_layer", &Summary::start_layer, "1-based.")
      .def_readonly("num_layers", &Summary::num_layers, "Layers of the map.")
      .def_readonly("finest_cell_size_m",
                    &Summary::finest_cell_size_m,
                    "Cell edge of the last layer [m].")
      .def_property_readonly(
          "trace",
          &TraceList,
          "One dict per iteration: iteration, layer, score, step_norm, "
          "step_is_successful, reference_from_input_xi (m, rad), time_s "
          "(from the registration's start).")
      .def_readonly("input_points", &Summary::input_points)
      .def_readonly("range_filtered_points",
                    &Summary::range_filtered_points,
                    "Input points dropped by the range filter.")
      .def_readonly("sampled_points",
                    &Summary::sampled_points,
                    "Input points that became residuals.")
      .def_readonly("matched_points",
                    &Summary::matched_points,
                    "Sampled points in a cell at the solution.")
      .def_readonly("unmatched_points", &Summary::unmatched_points)
      .def_readonly("map_occupied_cells",
                    &Summary::map_occupied_cells,
                    "Over all layers of the map.")
      .def_readonly("map_bytes", &Summary::map_bytes, "The map's memory.")
      .def_readonly("total_time_s",
                    &Summary::total_time_s,
                    "Wall time of the library call [s] (map, sampling and "
                    "solve; mlndt_align's time_ms.total).")
      .def_readonly("map_time_s",
                    &Summary::map_time_s,
                    "Building the map [s] (0 when given).")
      .def_readonly("sampling_time_s", &Summary::sampling_time_s, "[s].")
      .def_readonly("solve_time_s", &Summary::solve_time_s, "[s].")
      .def("report",
           &Summary::FullReport,
           "report() -> str\n\nThe library's FullReport (what mlndt_align "
           "prints).")
      .def("brief_report",
           &Summary::BriefReport,
           "brief_report() -> str\n\nThe library's one-line BriefReport.")
      .def("__repr__", [](const Summary& s) {
        return "<mlndt.RegistrationResult " + s.BriefReport() + ">";
      });
}

void DefineResult(py::module_& m) {
  py::class_<Summary> result(
      m,
      "RegistrationResult",
      "What a registration reports (mlndt::RegistrationSummary): the pose, "
      "the verdict, the fit, the covariance, the trace and timings. Poses "
      "map input points into the reference frame.");
  DefinePoseAndVerdict(result);
  DefineEvidence(result);
  DefineCountsAndReports(result);
}

}  // namespace

RegistrationSummary RegisterReleasingGil(const RegistrationOptions& options,
                                         const LayeredGrid* map,
                                         const PointCloud* reference,
                                         const PointCloud& input,
                                         const Isometry3d& initial) {
  RegistrationSummary summary;
  py::gil_scoped_release release;
  if (map != nullptr) {
    mlndt::Register(options, *map, input, initial, &summary);
  } else {
    mlndt::Register(options, *reference, input, initial, &summary);
  }
  return summary;
}

std::string RegisterArgumentsDoc() {
  return "initial: 4x4 (or 3x4) rigid transform, the guess of "
         "reference_from_input\n"
         "    (maps input points into the reference frame); None: "
         "identity.\n"
         "initial_uncertainty: (translation_m, rotation_deg), how far the "
         "guess may be\n"
         "    off: picks the start layer and a guess is never made worse; "
         "None: unknown.\n"
         "preset: \"default\" (RegistrationOptions()) or \"paper\"\n"
         "    (PaperRegistrationOptions()); the other options change it.\n"
         "\n"
         "Options are keyword arguments named as the fields of "
         "mlndt::RegistrationOptions;\n"
         "a nested struct is a dict of its fields (only those given "
         "change), enums are\n"
         "strings in any case, e.g. grid={\"finest_cell_size_m\": 1.0}, "
         "backend={\"type\": \"lm\"}.\n"
         "mlndt.default_options() returns them all. The library's IsValid "
         "checks them.\n" +
         RegistrationOptionsDoc() +
         "\n"
         "Returns a RegistrationResult. A registration that ends badly is "
         "not an exception:\n"
         "its termination says FAILURE, LOW_QUALITY or DEGENERATE and its "
         "message why;\n"
         "check result.usable.\n"
         "\n"
         "Raises ValueError for an unknown option or an invalid value "
         "(naming the field),\n"
         "a cloud of the wrong shape, an empty cloud, a non-finite row or a "
         "guess that is\n"
         "not a rigid transform; TypeError for a non-numeric array.\n"
         "\n"
         "The GIL is released while the library runs: threads register in "
         "parallel.\n";
}

void DefineRegistration(py::module_& m) {
  DefineResult(m);
  m.def("register",
        &Register,
        py::arg("reference"),
        py::arg("input"),
        py::arg("initial") = py::none(),
        py::arg("initial_uncertainty") = py::none(),
        ("register(reference, input, initial=None, initial_uncertainty=None, "
         "**options) -> RegistrationResult\n\n"
         "Registers the input scan onto the reference scan with ML-NDT "
         "(mlndt::Register):\n"
         "builds the layered map of the reference, samples the input and "
         "runs the layer\n"
         "schedule (Table 1).\n"
         "\n"
         "reference, input: (N, 3) arrays of x, y, z [m], float64 or float32, "
         "any strides\n"
         "    (copied once into the library's clouds; float32 converted on "
         "the way).\n" +
         RegisterArgumentsDoc())
            .c_str());
}

}  // namespace python
}  // namespace mlndt
