#include "mlndt/registration/registration_options.h"

#include "mlndt/common/internal/check_option.h"
#include "mlndt/common/option_table.h"

namespace mlndt {

const OptionTable& InitialGuessUncertaintyTable() {
  using S = InitialGuessUncertainty;
  static const OptionTable table =
      OptionTableBuilder<S>("InitialGuessUncertainty")
          .Bool("given",
                &S::given,
                "False: nothing is known about the guess (schedule.start_layer "
                "applies).")
          .Double("translation_m",
                  &S::translation_m,
                  "m",
                  Closed(0.0, 1e4),
                  "How far the guess may be off.")
          .Double("rotation_deg",
                  &S::rotation_deg,
                  "deg",
                  Closed(0.0, 180.0),
                  "How far the guess may be turned.")
          .Validator(&S::IsValid)
          .Build();
  return table;
}

bool InitialGuessUncertainty::IsValid(std::string* error) const {
  return InitialGuessUncertaintyTable().Check(*this, error);
}

const OptionTable& RetryOptionsTable() {
  using S = RetryOptions;
  static const OptionTable table =
      OptionTableBuilder<S>("RetryOptions")
          .DoubleList("yaw_seeds_deg",
                      &S::yaw_seeds_deg,
                      "deg",
                      Closed(-180.0, 180.0),
                      "Yaw turns of the guess tried, in order, until a result "
                      "converges and passes the quality check; empty = no "
                      "retry. At most 36.")
          .Int("weak_direction_rounds",
               &S::weak_direction_rounds,
               Closed(0, 16),
               "Rounds of the search along the flattest weak direction: the "
               "last layer again from the solution moved one cell edge along "
               "it, both ways; a better fit in another basin replaces it. "
               "0 = off.")
          .Double("weak_direction_min_flatness",
                  &S::weak_direction_min_flatness,
                  "",
                  Closed(0.0, 1.0),
                  "The search along the flattest weak direction runs only "
                  "when the probe kept at least this share of the inliers one "
                  "cell edge along it (the result's flatness); the scan-"
                  "pattern check looks beyond the pattern only when the "
                  "planar cells keep this share one cell edge along the "
                  "weakest translation.")
          .Double("scan_pattern_reach_cells",
                  &S::scan_pattern_reach_cells,
                  "",
                  Closed(0.0, 4.0),
                  "A converged result whose translation is within this many "
                  "last-layer cell edges of zero (the sensors coincide, and "
                  "so do a spinning LiDAR's rings) is checked against the "
                  "last layer without its line cells, and (where that "
                  "translation is flat) the last layer runs again from 1 + "
                  "this many cell edges along its weakest translation; 0 = "
                  "off.")
          .Validator(&S::IsValid)
          .Build();
  return table;
}

bool RetryOptions::IsValid(std::string* error) const {
  MLNDT_OPTION_LE(yaw_seeds_deg.size(), size_t{36});
  return RetryOptionsTable().Check(*this, error);
}

const OptionTable& RegistrationOptionsTable() {
  using S = RegistrationOptions;
  static const OptionTable table =
      OptionTableBuilder<S>("RegistrationOptions")
          .Struct("range_filter",
                  &S::range_filter,
                  RangeFilterOptionsTable(),
                  "Returns dropped from the input (and from the reference "
                  "when the map is built here).")
          .Struct("grid",
                  &S::grid,
                  LayeredGridOptionsTable(),
                  "The reference map (not for LayeredMap.register: the map "
                  "exists).")
          .Struct("sampling",
                  &S::sampling,
                  SamplingOptionsTable(),
                  "Which input points become residuals (Section 4.3).")
          .Struct("schedule",
                  &S::schedule,
                  LayerScheduleOptionsTable(),
                  "Start layer, iterations per layer, convergence (Table 1).")
          .Struct("objective",
                  &S::objective,
                  ObjectiveOptionsTable(),
                  "What is minimised (Eq. 10).")
          .Struct("backend",
                  &S::backend,
                  BackendOptionsTable(),
                  "Which minimiser, with its options.")
          .Int("num_threads",
               &S::num_threads,
               Closed(1, 256),
               "Threads for the map build and the backend (the Ceres "
               "backend's residual evaluation, or OpenMP threads for newton "
               "and lm); work too small to share stays on one thread. Ceres: "
               "the same result for any count. newton/lm with > 1 on a "
               "loaded machine: set OMP_WAIT_POLICY=passive.")
          .Double("min_matched_fraction",
                  &S::min_matched_fraction,
                  "",
                  Closed(0.0, 1.0),
                  "FAILURE when fewer than this fraction of the sampled "
                  "points are matched at the solution.")
          .Struct("quality_check",
                  &S::quality_check,
                  QualityCheckOptionsTable(),
                  "Whether the result can be trusted (quality_check.h).")
          .Struct("initial_uncertainty",
                  &S::initial_uncertainty,
                  InitialGuessUncertaintyTable(),
                  "How good the initial guess is; the initial_uncertainty "
                  "argument sets it.")
          .Struct("retry",
                  &S::retry,
                  RetryOptionsTable(),
                  "Runs from turned guesses when the first fails the quality "
                  "check.")
          .Validator(&S::IsValid)
          .Build();
  return table;
}

bool RegistrationOptions::IsValid(std::string* error) const {
  if (!quality_check.IsValid(error) || !initial_uncertainty.IsValid(error) ||
      !retry.IsValid(error) || !range_filter.IsValid(error) ||
      !grid.IsValid(error) || !sampling.IsValid(error) ||
      !schedule.IsValid(error) || !objective.IsValid(error) ||
      !backend.IsValid(error)) {
    return false;
  }
  return RegistrationOptionsTable().Check(*this, error);
}

RegistrationOptions PaperRegistrationOptions() {
  RegistrationOptions options;
  options.grid = PaperLayeredGridOptions();
  options.schedule = PaperLayerScheduleOptions();
  options.objective = PaperObjectiveOptions();
  options.backend.type = BackendType::NEWTON;
  options.retry.yaw_seeds_deg.clear();
  options.retry.weak_direction_rounds = 0;
  options.retry.scan_pattern_reach_cells = 0.0;
  return options;
}

}  // namespace mlndt
