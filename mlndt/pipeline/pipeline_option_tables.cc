#include "mlndt/pipeline/pipeline_option_tables.h"

#include "mlndt/odometry/odometry_option_tables.h"
#include "mlndt/pipeline/localizer.h"
#include "mlndt/pipeline/map_builder.h"

namespace mlndt {

const OptionTable& MapBuildOwnOptionsTable() {
  using S = MapBuildOptions;
  static const OptionTable table =
      OptionTableBuilder<S>("MapBuildOptions")
          .Double("voxel_size_m",
                  &S::voxel_size_m,
                  "m",
                  ClosedOrZero(1e-3, 1e3),
                  "Voxel edge of the filter of the merged cloud (one "
                  "centroid per voxel); 0 = no filter.")
          .Uint64("max_memory_bytes",
                  &S::max_memory_bytes,
                  "Memory the build may hold at once [bytes]: the merged "
                  "cloud plus the voxel filter's or the map build's working "
                  "memory; 0 = no limit.")
          .Int("num_threads",
               &S::num_threads,
               Closed(1, 256),
               "Threads of the map build (LayeredGrid::Build).")
          .Validator(&S::IsValid)
          .Build();
  return table;
}

const OptionTable& PriorCheckOptionsTable() {
  using S = PriorCheckOptions;
  static const OptionTable table =
      OptionTableBuilder<S>("PriorCheckOptions")
          .Bool("explore",
                &S::explore,
                "Register the scan again from starts on the prior's "
                "half-bound (+-x, +-y, +-yaw in the guess's frame) and keep "
                "the best fit within the prior (localization_prior.h).")
          .Double("explore_min_rotation_deg",
                  &S::explore_min_rotation_deg,
                  "deg",
                  Closed(0.0, 180.0),
                  "A prior's rotation up to this is not explored (one basin "
                  "holds it); its translation is explored beyond the finest "
                  "cell edge.")
          .Double("explore_distinct_rotation_deg",
                  &S::explore_distinct_rotation_deg,
                  "deg",
                  LeftOpen(0.0, 180.0),
                  "Two results are distinct minima beyond half a finest "
                  "cell edge or this rotation apart.")
          .Double("ambiguity_inlier_margin",
                  &S::ambiguity_inlier_margin,
                  "",
                  Closed(0.0, 1.0),
                  "A distinct minimum within the prior whose inlier "
                  "fraction is at least the best's minus this fits as well: "
                  "the scan is DEGENERATE.")
          .Double("min_fit_ratio",
                  &S::min_fit_ratio,
                  "",
                  Closed(0.0, 1.0),
                  "A result is kept when its inlier fraction is at least "
                  "this times the share of a Gaussian within the quality "
                  "check's gate (the map's own points' fit); 0 = off.")
          .Validator(&S::IsValid)
          .Build();
  return table;
}

const OptionTable& LocalizerOwnOptionsTable() {
  using S = LocalizerOptions;
  static const OptionTable table =
      OptionTableBuilder<S>("LocalizerOptions")
          .Enum("motion_model",
                &S::motion_model,
                MotionModelTable(),
                "Initial guess of scan k > 0: constant_velocity (pose_{k-1} "
                "moved by the last relative motion) or constant_pose "
                "(pose_{k-1}); after an unusable scan the last usable pose.")
          .Double("guess_translation_m",
                  &S::guess_translation_m,
                  "m",
                  Closed(0.0, 1e4),
                  "How far the first scan's guess (and each --guesses pose) "
                  "may be from the truth; 0 with guess_rotation_deg 0: not "
                  "stated.")
          .Double("guess_rotation_deg",
                  &S::guess_rotation_deg,
                  "deg",
                  Closed(0.0, 180.0),
                  "The same in rotation.")
          .Double("prediction_translation_m",
                  &S::prediction_translation_m,
                  "m",
                  Closed(0.0, 1e4),
                  "How far the prediction after a usable scan may be from "
                  "the truth; 0 with prediction_rotation_deg 0: not stated.")
          .Double("prediction_rotation_deg",
                  &S::prediction_rotation_deg,
                  "deg",
                  Closed(0.0, 180.0),
                  "The same in rotation.")
          .Bool("adapt_prediction_uncertainty",
                &S::adapt_prediction_uncertainty,
                "With prediction_translation_m and prediction_rotation_deg "
                "0: the prediction's uncertainty from its recent errors "
                "(adaptive_uncertainty_*, as the odometry's); false: not "
                "stated.")
          .Struct("adaptive_uncertainty",
                  &S::adaptive_uncertainty,
                  MotionPredictionOptionsTable(),
                  "The prediction's uncertainty from its recent errors "
                  "(motion_prediction.h).")
          .Double("lost_translation_m_per_scan",
                  &S::lost_translation_m_per_scan,
                  "m",
                  Closed(0.0, 1e3),
                  "Added to the prediction's uncertainty per unusable scan "
                  "since the last usable one.")
          .Double("lost_rotation_deg_per_scan",
                  &S::lost_rotation_deg_per_scan,
                  "deg",
                  Closed(0.0, 180.0),
                  "The same in rotation.")
          .Double("max_lost_translation_m",
                  &S::max_lost_translation_m,
                  "m",
                  Closed(0.0, 1e4),
                  "The growth stops here.")
          .Double("max_lost_rotation_deg",
                  &S::max_lost_rotation_deg,
                  "deg",
                  Closed(0.0, 180.0),
                  "The growth stops here.")
          .Struct("prior_check",
                  &S::prior_check,
                  PriorCheckOptionsTable(),
                  "A result against its prior (localization_prior.h).")
          .Validator(&S::IsValid)
          .Build();
  return table;
}

}  // namespace mlndt
