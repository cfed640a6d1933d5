#include "lab/experiments/gap_pairs.h"

#include <algorithm>
#include <sstream>

#include "mlndt/common/pose.h"

namespace mlndt {
namespace {

// The initial guess of run k and its label: the identity, or the truth
// pushed off by perturbation k in the reference frame.
Isometry3d InitialGuess(const std::vector<Vector6d>& perturbations,
                        size_t k,
                        const Isometry3d& truth,
                        std::string* label) {
  if (perturbations.empty()) {
    *label = "identity";
    return Isometry3d::Identity();
  }
  std::ostringstream l;
  const Vector6d& p = perturbations[k];
  l << "gt+(" << p(0) << "," << p(1) << "," << p(2) << "," << p(3) * kRadToDeg
    << "," << p(4) * kRadToDeg << "," << p(5) * kRadToDeg << ")";
  *label = l.str();
  return PoseVectorToIsometry(perturbations[k]) * truth;
}

}  // namespace

void RunGapPairs(const GapPairsOptions& pairs,
                 const RegistrationOptions& options,
                 const std::vector<PointCloud>& scans,
                 const std::vector<Isometry3d>& world_from_scan,
                 const std::function<void(const GapPairRun&)>& on_run) {
  const size_t runs = std::max<size_t>(1, pairs.perturbations.size());
  for (const size_t gap : pairs.gaps) {
    for (size_t i = 0; i + gap < scans.size(); ++i) {
      const size_t j = i + gap;
      const Isometry3d truth =
          world_from_scan[i].inverse() * world_from_scan[j];
      for (size_t k = 0; k < runs; ++k) {
        GapPairRun run;
        run.reference = i;
        run.input = j;
        run.gap = gap;
        const Isometry3d initial =
            InitialGuess(pairs.perturbations, k, truth, &run.start);
        RegistrationSummary summary;
        Register(options, scans[i], scans[j], initial, &summary);
        const Isometry3d& estimate = summary.reference_from_input;
        run.translation_error_m = TranslationErrorM(truth, estimate);
        run.rotation_error_deg = RotationErrorRad(truth, estimate) * kRadToDeg;
        run.success = summary.IsSolutionUsable() &&
                      run.translation_error_m < pairs.max_translation_error_m &&
                      run.rotation_error_deg < pairs.max_rotation_error_deg;
        run.termination = summary.termination_type;
        run.iterations = summary.num_iterations;
        run.time_ms = summary.total_time_s * 1e3;
        on_run(run);
      }
    }
  }
}

}  // namespace mlndt
