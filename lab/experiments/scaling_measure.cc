#include "lab/experiments/scaling_measure.h"

#include <glog/logging.h>

#include <cmath>

#include "lab/eval/statistics.h"
#include "lab/report/text_format.h"
#include "mlndt/common/pose.h"
#include "mlndt/sampling/point_sampler.h"

namespace mlndt {

// `n` distinct points of `cloud`, uniformly at random, kept in the cloud's
// order: the library's random sampling with an exact count.
namespace {

PointCloud RandomSubset(const PointCloud& cloud, size_t n, uint64_t seed) {
  SamplingOptions options;
  options.method = SamplingMethod::RANDOM;
  options.random_count = n;
  options.seed = seed;
  PointCloud subset;
  std::string error;
  CHECK(SamplePoints(options, cloud, &subset, nullptr, &error)) << error;
  return subset;
}

}  // namespace

bool MeasureSize(const ScalingSettings& settings,
                 const MatcherOptions& options,
                 const PointCloud& merged,
                 size_t n,
                 const Isometry3d& reference_from_input,
                 SizeResult* result,
                 std::string* error) {
  *result = SizeResult();
  result->points = n;
  // Two independent subsets: seeds differ per size and per role.
  const uint64_t seed = settings.seed * 0x9E3779B97F4A7C15ull + n;
  const PointCloud reference = RandomSubset(merged, n, seed * 2);
  const PointCloud input = TransformCloud(
      reference_from_input.inverse(), RandomSubset(merged, n, seed * 2 + 1));

  if (options.method == Method::MLNDT) {
    // Untimed, for the cell count (and a warm-up of the allocator).
    LayeredGrid grid;
    if (!LayeredGrid::Build(options.mlndt.grid, reference, &grid, error)) {
      *error = "N = " + std::to_string(n) + ": map: " + *error;
      return false;
    }
    result->finest_cells = grid.layer_info().back().occupied_cells;
    result->num_layers = grid.num_layers();
  }

  std::vector<double> map_ms, sampling_ms, solve_ms, total_ms;
  RegistrationSummary summary;
  for (int r = 0; r < settings.repetitions; ++r) {
    RegisterWithMatcher(
        options, reference, input, Isometry3d::Identity(), &summary);
    map_ms.push_back(summary.map_time_s * 1e3);
    sampling_ms.push_back(summary.sampling_time_s * 1e3);
    solve_ms.push_back(summary.solve_time_s * 1e3);
    total_ms.push_back(summary.total_time_s * 1e3);
  }
  result->map_ms = ComputeStats(map_ms).median;
  result->sampling_ms = ComputeStats(sampling_ms).median;
  result->solve_ms = ComputeStats(solve_ms).median;
  result->total_ms = ComputeStats(total_ms).median;
  // Registration is deterministic: the last run stands for all.
  result->sampled_points = summary.sampled_points;
  result->iterations = summary.num_iterations;
  if (summary.num_layers > 0) result->num_layers = summary.num_layers;
  result->termination = summary.termination_type;
  result->message = summary.message;
  result->translation_error_m =
      TranslationErrorM(reference_from_input, summary.reference_from_input);
  result->rotation_error_deg =
      RotationErrorRad(reference_from_input, summary.reference_from_input) *
      kRadToDeg;
  result->ok =
      summary.IsSolutionUsable() &&
      result->translation_error_m <= settings.max_translation_error_m &&
      result->rotation_error_deg <= settings.max_rotation_error_deg;
  return true;
}

bool MeasureSizes(const ScalingSettings& settings,
                  const MatcherOptions& options,
                  const PointCloud& merged,
                  const std::vector<size_t>& sizes,
                  const Isometry3d& reference_from_input,
                  ProgressCallback* progress,
                  std::vector<SizeResult>* results,
                  std::string* error) {
  results->assign(sizes.size(), SizeResult());
  for (size_t k = 0; k < sizes.size(); ++k) {
    if (!MeasureSize(settings,
                     options,
                     merged,
                     sizes[k],
                     reference_from_input,
                     &(*results)[k],
                     error)) {
      return false;
    }
    ReportProgress(progress,
                   {k,
                    k + 1,
                    sizes.size(),
                    "N = " + std::to_string(sizes[k]) + ", total " +
                        Fmt((*results)[k].total_ms, 1) + " ms"});
  }
  return true;
}

}  // namespace mlndt
