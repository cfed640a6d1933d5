// mlndt_lab's trajectory evaluation: pairing poses (association), the ATE
// and RPE (lab/eval/trajectory_metrics.h) and the KITTI devkit's segment
// errors (lab/eval/kitti_segment_errors.h), as mlndt_eval computes them.

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <string>
#include <vector>

#include "lab/eval/kitti_segment_errors.h"
#include "lab/eval/trajectory.h"
#include "lab/eval/trajectory_association.h"
#include "lab/eval/trajectory_metrics.h"
#include "lab/python/src/lab_module.h"

namespace mlndt {
namespace python {
namespace {

py::dict StatsDict(const Stats& s) {
  py::dict d;
  d["count"] = s.count;
  d["mean"] = s.mean;
  d["std"] = s.std;
  d["min"] = s.min;
  d["max"] = s.max;
  d["median"] = s.median;
  d["p95"] = s.p95;
  return d;
}

// A trajectory from poses and optional timestamps (None: 0, 1, 2, ...).
Trajectory TrajectoryFromPython(py::handle poses,
                                py::handle timestamps,
                                const std::string& what) {
  const std::vector<Isometry3d> list = PosesFromPython(poses, what.c_str());
  if (timestamps.is_none()) return Trajectory(list);
  const auto times = timestamps.cast<std::vector<double>>();
  if (times.size() != list.size()) {
    throw py::value_error(
        what + "_timestamps: " + std::to_string(times.size()) +
        " timestamps for " + std::to_string(list.size()) + " poses");
  }
  Trajectory trajectory;
  for (size_t k = 0; k < list.size(); ++k) {
    if (!std::isfinite(times[k]) || (k > 0 && !(times[k] > times[k - 1]))) {
      throw py::value_error(what + "_timestamps[" + std::to_string(k) +
                            "]: timestamps must be finite and increase "
                            "strictly");
    }
    trajectory.Add(times[k], list[k]);
  }
  return trajectory;
}

py::dict Associate(const py::object& reference,
                   const py::object& estimate,
                   const py::object& reference_timestamps,
                   const py::object& estimate_timestamps,
                   double max_time_difference_s) {
  const bool by_time =
      !reference_timestamps.is_none() || !estimate_timestamps.is_none();
  if (by_time &&
      (reference_timestamps.is_none() || estimate_timestamps.is_none())) {
    throw py::value_error(
        "reference_timestamps, estimate_timestamps: give both (timestamp "
        "association) or neither (index association)");
  }
  if (by_time && !(max_time_difference_s > 0)) {
    throw py::value_error("max_time_difference_s: must be > 0, got " +
                          std::to_string(max_time_difference_s));
  }
  const Trajectory r =
      TrajectoryFromPython(reference, reference_timestamps, "reference");
  const Trajectory e =
      TrajectoryFromPython(estimate, estimate_timestamps, "estimate");
  const AssociatedPoses pairs =
      by_time ? AssociateByTimestamp(r, e, max_time_difference_s)
              : AssociateByIndex(r, e);
  py::dict d;
  d["reference_indices"] = py::array(py::cast(pairs.reference_indices));
  d["estimate_indices"] = py::array(py::cast(pairs.estimate_indices));
  d["reference"] = PosesToPython(pairs.reference);
  d["estimate"] = PosesToPython(pairs.estimate);
  return d;
}

py::dict Ate(const py::object& reference,
             const py::object& estimate,
             const std::string& alignment) {
  AteOptions options;
  if (!StringToTrajectoryAlignment(alignment, &options.alignment)) {
    throw py::value_error("alignment = '" + alignment +
                          "': expected se3, sim3, first_pose or none");
  }
  AteSummary s;
  std::string error;
  if (!ComputeAte(options,
                  PosesFromPython(reference, "reference"),
                  PosesFromPython(estimate, "estimate"),
                  &s,
                  &error)) {
    throw py::value_error("ate: " + error);
  }
  Eigen::Matrix4d a = Eigen::Matrix4d::Identity();
  a.topLeftCorner<3, 3>() =
      s.reference_from_estimate.scale * s.reference_from_estimate.rotation;
  a.topRightCorner<3, 1>() = s.reference_from_estimate.translation;
  py::dict d;
  d["rmse_m"] = s.rmse_m;
  d["errors_m"] = py::array(py::cast(s.errors_m));
  d["stats_m"] = StatsDict(s.errors);
  d["scale"] = s.reference_from_estimate.scale;
  d["reference_from_estimate"] = a;
  return d;
}

py::dict Rpe(const py::object& reference,
             const py::object& estimate,
             int delta) {
  RpeOptions options;
  options.delta = delta;
  RpeSummary s;
  std::string error;
  if (!ComputeRpe(options,
                  PosesFromPython(reference, "reference"),
                  PosesFromPython(estimate, "estimate"),
                  &s,
                  &error)) {
    throw py::value_error("rpe: " + error);
  }
  py::dict d;
  d["translation_rmse_m"] = s.translation_rmse_m;
  d["rotation_rmse_deg"] = s.rotation_rmse_deg;
  d["translation_m"] = StatsDict(s.translation_m);
  d["rotation_deg"] = StatsDict(s.rotation_deg);
  return d;
}

py::list LengthList(const KittiSegmentSummary& s) {
  py::list lengths;
  for (const KittiLengthErrors& l : s.lengths) {
    py::dict d;
    d["length_m"] = l.length_m;
    d["segments"] = l.num_segments;
    d["translation_error_percent"] = l.translation_error_percent;
    d["rotation_error_deg_per_m"] = l.rotation_error_deg_per_m;
    lengths.append(std::move(d));
  }
  return lengths;
}

py::dict KittiSegments(const py::object& reference,
                       const py::object& estimate,
                       const std::vector<double>& lengths_m,
                       int first_frame_step) {
  KittiSegmentOptions options;
  options.lengths_m = lengths_m;
  options.first_frame_step = first_frame_step;
  KittiSegmentSummary s;
  std::string error;
  if (!ComputeKittiSegmentErrors(options,
                                 PosesFromPython(reference, "reference"),
                                 PosesFromPython(estimate, "estimate"),
                                 &s,
                                 &error)) {
    throw py::value_error("kitti_segment_errors: " + error);
  }
  const py::ssize_t n = static_cast<py::ssize_t>(s.segments.size());
  py::array_t<double> segments({n, py::ssize_t{5}});
  auto out = segments.mutable_unchecked<2>();
  for (py::ssize_t k = 0; k < n; ++k) {
    const KittiSegment& g = s.segments[static_cast<size_t>(k)];
    out(k, 0) = static_cast<double>(g.first_frame);
    out(k, 1) = static_cast<double>(g.last_frame);
    out(k, 2) = g.length_m;
    out(k, 3) = g.translation_error;
    out(k, 4) = g.rotation_error;
  }
  py::dict d;
  d["segments"] = segments;
  d["lengths"] = LengthList(s);
  d["translation_error_percent"] = s.translation_error_percent;
  d["rotation_error_deg_per_m"] = s.rotation_error_deg_per_m;
  return d;
}

}  // namespace

void DefineEvaluation(py::module_& m) {
  m.def("associate",
        &Associate,
        py::arg("reference"),
        py::arg("estimate"),
        py::arg("reference_timestamps") = py::none(),
        py::arg("estimate_timestamps") = py::none(),
        py::arg("max_time_difference_s") = 0.02,
        "associate(reference, estimate, reference_timestamps=None,\n"
        "          estimate_timestamps=None, max_time_difference_s=0.02) "
        "-> dict\n\n"
        "Pairs the poses of two trajectories ((N, 4, 4) world_from_sensor) "
        "that describe\nthe same instant: by index without timestamps "
        "(KITTI), else each estimate pose\nwith the nearest reference "
        "pose within max_time_difference_s [s] (TUM;\n"
        "lab/eval/trajectory_association.h). Returns reference_indices, "
        "estimate_indices\nand the paired poses reference, estimate "
        "((K, 4, 4)).");
  m.def("ate",
        &Ate,
        py::arg("reference"),
        py::arg("estimate"),
        py::arg("alignment") = "se3",
        "ate(reference, estimate, alignment=\"se3\") -> dict\n\n"
        "Absolute trajectory error of paired poses (see associate): e_k = "
        "|t(reference_k) -\nA t(estimate_k)| [m] after the alignment A "
        "(se3, sim3: Umeyama fits of the\npositions; first_pose; none). "
        "Returns rmse_m, errors_m, stats_m (count, mean,\nstd, min, max, "
        "median, p95), scale and reference_from_estimate (4x4, scale in\n"
        "its 3x3). mlndt_eval's ate numbers. ValueError on different sizes, "
        "no poses or a\nfailed fit.");
  m.def("rpe",
        &Rpe,
        py::arg("reference"),
        py::arg("estimate"),
        py::arg("delta") = 1,
        "rpe(reference, estimate, delta=1) -> dict\n\n"
        "Relative pose error over pairs (k, k + delta): translation "
        "|t(Q) - t(P)| [m] and\nrotation angle(R(Q)^T R(P)) [deg] of the "
        "relative motions Q (reference) and P\n(estimate). Returns "
        "translation_rmse_m, rotation_rmse_deg and the stats dicts\n"
        "translation_m, rotation_deg. ValueError on different sizes, delta "
        "< 1 or too few\nposes.");
  m.def("kitti_segment_errors",
        &KittiSegments,
        py::arg("reference"),
        py::arg("estimate"),
        py::arg("lengths_m") =
            std::vector<double>{100, 200, 300, 400, 500, 600, 700, 800},
        py::arg("first_frame_step") = 10,
        "kitti_segment_errors(reference, estimate, lengths_m=(100, ..., "
        "800),\n                     first_frame_step=10) -> dict\n\n"
        "The KITTI odometry devkit's errors over path segments "
        "(lab/eval/kitti_segment_errors.h):\n"
        "translation_error_percent and rotation_error_deg_per_m over all "
        "segments (NaN when\nthere is none), lengths (one dict per length "
        "that has segments) and segments, a\n(S, 5) array of first_frame, "
        "last_frame, length_m, translation error [m/m],\nrotation error "
        "[rad/m]. ValueError on different sizes, no poses, a length <= 0 "
        "or\ngiven twice, first_frame_step < 1.");
  m.def(
      "path_distances_m",
      [](const py::object& poses) {
        return py::array(
            py::cast(PathDistancesM(PosesFromPython(poses, "poses"))));
      },
      py::arg("poses"),
      "path_distances_m(poses) -> numpy.ndarray\n\n"
      "Path length from the first pose to each pose [m] (the devkit's "
      "trajectoryDistances).");
}

}  // namespace python
}  // namespace mlndt
