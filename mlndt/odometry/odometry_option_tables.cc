#include "mlndt/odometry/odometry_option_tables.h"

#include "mlndt/odometry/confirm_pose.h"
#include "mlndt/odometry/keyframe_policy.h"
#include "mlndt/odometry/local_map.h"
#include "mlndt/odometry/motion_prediction.h"
#include "mlndt/odometry/odometry_options.h"
#include "mlndt/odometry/recovery.h"

namespace mlndt {

const OptionTable& LocalMapOptionsTable() {
  using S = LocalMapOptions;
  static const OptionTable table =
      OptionTableBuilder<S>("LocalMapOptions")
          .Int("max_keyframes",
               &S::max_keyframes,
               AtLeast(1),
               "Keyframes kept in the local map (the oldest is dropped "
               "first).")
          .Double("radius_m",
                  &S::radius_m,
                  "m",
                  LeftOpen(0.0, 1e9),
                  "Map points farther than this from the newest keyframe are "
                  "left out.")
          .Validator(&S::IsValid)
          .Build();
  return table;
}

const OptionTable& KeyframeOptionsTable() {
  using S = KeyframeOptions;
  static const OptionTable table =
      OptionTableBuilder<S>("KeyframeOptions")
          .Double("min_translation_m",
                  &S::min_translation_m,
                  "m",
                  LeftOpen(0.0, 1e9),
                  "A scan joins the local map this far from the last "
                  "keyframe...")
          .Double("min_rotation_deg",
                  &S::min_rotation_deg,
                  "deg",
                  LeftOpen(0.0, 1e9),
                  "... or turned this much.")
          .Validator(&S::IsValid)
          .Build();
  return table;
}

const OptionTable& MotionPredictionOptionsTable() {
  using S = MotionPredictionOptions;
  static const OptionTable table =
      OptionTableBuilder<S>("MotionPredictionOptions")
          .Int("window",
               &S::window,
               AtLeast(1),
               "Recent model errors the uncertainty uses.")
          .Double("factor",
                  &S::factor,
                  "",
                  AtLeast(1.0),
                  "Uncertainty = their maximum x factor.")
          .Double("min_translation_m",
                  &S::min_translation_m,
                  "m",
                  AtLeast(0.0),
                  "Lower bound of the translation uncertainty.")
          .Double("max_translation_m",
                  &S::max_translation_m,
                  "m",
                  AtLeast(0.0),
                  "Upper bound (also the largest correction accepted); >= "
                  "min_translation_m.")
          .Double("min_rotation_deg",
                  &S::min_rotation_deg,
                  "deg",
                  Closed(0.0, 180.0),
                  "Lower bound of the rotation uncertainty.")
          .Double("max_rotation_deg",
                  &S::max_rotation_deg,
                  "deg",
                  Closed(0.0, 180.0),
                  "Upper bound (also the largest correction accepted); >= "
                  "min_rotation_deg.")
          .Validator(&S::IsValid)
          .Build();
  return table;
}

const OptionTable& ConfirmationOptionsTable() {
  using S = ConfirmationOptions;
  static const OptionTable table =
      OptionTableBuilder<S>("ConfirmationOptions")
          .Bool("enabled",
                &S::enabled,
                "Confirm CONVERGENCE by a second registration from beyond "
                "the pose (NO_CONVERGENCE when it does not return).")
          .Double("min_correction_fraction",
                  &S::min_correction_fraction,
                  "",
                  AtLeast(0.0),
                  "Confirm a correction above this fraction of the "
                  "prediction's uncertainty (and any from its largest); 0 = "
                  "every scan.")
          .Bool("check_last_scan",
                &S::check_last_scan,
                "A pose the second run returned to must also agree with the "
                "scan registered onto the last registered scan alone.")
          .Bool("last_scan_confirms",
                &S::last_scan_confirms,
                "A pose the second run did not return to is confirmed when "
                "the scan registered onto the last registered scan alone "
                "agrees with it.")
          .Validator(&S::IsValid)
          .Build();
  return table;
}

const OptionTable& RecoveryOptionsTable() {
  using S = RecoveryOptions;
  static const OptionTable table =
      OptionTableBuilder<S>("RecoveryOptions")
          .Int("max_search_starts",
               &S::max_search_starts,
               Closed(0, 5),
               "Starts onto the local map tried for a scan not registered "
               "from its prediction (the last registered pose, then the "
               "prediction and the last pose turned by +-yaw_step_deg; after "
               "skipped scans the dead-reckoned pose first, besides); 0 = "
               "none.")
          .Double("yaw_step_deg",
                  &S::yaw_step_deg,
                  "deg",
                  LeftOpen(0.0, 180.0),
                  "The turn about the sensor's z axis of the turned starts.")
          .Bool("register_onto_last_scan",
                &S::register_onto_last_scan,
                "Then register the scan onto the last registered scan "
                "alone, from the prediction.")
          .Validator(&S::IsValid)
          .Build();
  return table;
}

const OptionTable& OdometryOwnOptionsTable() {
  using S = OdometryOptions;
  static const OptionTable table = [] {
    OptionTableBuilder<S> builder("OdometryOptions");
    builder
        .Struct("local_map",
                &S::local_map,
                LocalMapOptionsTable(),
                "The local map of recent keyframes (its grid is grid=).")
        .Struct("keyframes",
                &S::keyframes,
                KeyframeOptionsTable(),
                "When a scan becomes a keyframe.")
        .Struct("prediction",
                &S::prediction,
                MotionPredictionOptionsTable(),
                "Constant-velocity prediction and its uncertainty.")
        .Bool("deskew", &S::deskew, "Deskew scans given point times.")
        .Double("gate_factor",
                &S::gate_factor,
                "",
                AtLeast(1.0),
                "A pose farther from the prediction than this times its "
                "uncertainty is refused (LOW_QUALITY).")
        .Struct("recovery",
                &S::recovery,
                RecoveryOptionsTable(),
                "The search for a scan not registered from its prediction.")
        .Struct("confirmation",
                &S::confirmation,
                ConfirmationOptionsTable(),
                "The confirmation of CONVERGENCE from beyond the pose.")
        .Validator(&S::IsValid);
    return builder.Build();
  }();
  return table;
}

}  // namespace mlndt
