#pragma once

// Localisation against a prebuilt map: every scan of a sequence is
// registered onto the same layered map (ML-NDT, registration.h), starting
// from a prediction of its pose.
//
//   Localizer localizer(options, map, first_map_from_scan);
//   for (each scan) {
//     LocalizationResult result;
//     localizer.Localize(scan, &result);
//   }
//
// Prediction (LocalizerOptions::motion_model): the first scan starts from
// the pose given to the constructor; with CONSTANT_VELOCITY scan k starts
// from pose_{k-1} * (pose_{k-2}^-1 * pose_{k-1}), the previous pose moved
// by the last relative motion (identity motion until two poses exist); with
// CONSTANT_POSE from pose_{k-1}. A registration whose result is not to be
// used (FAILURE, LOW_QUALITY or DEGENERATE: !IsSolutionUsable()) gets its
// prediction as its pose (flagged). No prediction is ever made from such a
// pose: after g unusable scans, scan k starts from the last usable pose
// (the velocity of a hand-held sensor's sweeps is not known across a gap)
// and the prediction's uncertainty grows with the gap (PredictionPrior).
//
// Each scan is registered within its prior (localization_prior.h): the
// guess with its stated uncertainty. A result outside the prior, or one
// that another minimum within the prior fits as well, is not usable.
//
// LocalizeScans runs the loop over a scan source that loads one scan at a
// time: the map and the current scan are the only clouds held.

#include <cstddef>
#include <deque>
#include <functional>
#include <string>
#include <vector>

#include "mlndt/cloud/point_cloud.h"
#include "mlndt/common/progress.h"
#include "mlndt/common/types.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/odometry/motion_prediction.h"
#include "mlndt/pipeline/localization_prior.h"
#include "mlndt/registration/registration.h"

namespace mlndt {

class EnumTable;
class ResultTable;

enum class MotionModel {
  CONSTANT_POSE,      // Scan k starts from pose_{k-1}.
  CONSTANT_VELOCITY,  // ... moved by the last relative motion.
};

// The names of MotionModel's values (enum_table.h).
const EnumTable& MotionModelTable();
const char* MotionModelToString(MotionModel model);
// Case-insensitive: "constant_pose", "constant_velocity".
bool StringToMotionModel(std::string value, MotionModel* model);

// The odometry's prediction model with its gate as the factor: the
// localiser's prior is both where it searches and what it accepts, as the
// odometry's gate is: gate_factor 3 x the uncertainty's factor 2 = 6 times
// the largest recent error (odometry_options.h).
inline MotionPredictionOptions LocalizerAdaptiveUncertainty() {
  MotionPredictionOptions options;
  options.factor = 6.0;
  return options;
}

// The localiser's registration defaults: the library's, without the
// localizability test (quality_check.min_localizability 0). The localiser
// accepts a pose only within its prior (localization_prior.h), which holds a
// direction the surfaces leave free; flagging such scans as well breaks the
// chain of predictions (docs/maps.md gives the measurement).
RegistrationOptions LocalizerRegistrationOptions();

struct LocalizerOptions {
  // The registration of each scan onto the map; `registration.grid` does not
  // apply (the map is built beforehand).
  RegistrationOptions registration = LocalizerRegistrationOptions();
  MotionModel motion_model = MotionModel::CONSTANT_VELOCITY;
  // How far the first scan's guess, and every guess given per scan
  // (Localizer::LocalizeFrom's callers), may be from the truth [m], [deg];
  // both 0: not stated (the registration's verdict stands alone).
  double guess_translation_m = 0.0;
  double guess_rotation_deg = 0.0;
  // How far the prediction of a scan whose previous scan was usable may be
  // from the truth [m], [deg]; both 0: not stated. It depends on the
  // sensor's motion (a car's 1 m between frames, a hand-held sensor's sweeps
  // of 15 deg): the caller states it (docs/maps.md).
  double prediction_translation_m = 0.0;
  double prediction_rotation_deg = 0.0;
  // With the prediction's uncertainty not stated: true takes it from the
  // prediction's recent errors, as the odometry does (motion_prediction.h):
  // `factor` x the largest of the last `window` differences between a
  // prediction and its usable result, within the bounds, and the maximum
  // before any is known. False leaves it not stated.
  bool adapt_prediction_uncertainty = true;
  MotionPredictionOptions adaptive_uncertainty = LocalizerAdaptiveUncertainty();
  // Added to the prediction's (or the first guess's) uncertainty per
  // unusable scan since the last usable one [m], [deg], up to the maxima
  // below; an uncertainty not stated stays not stated.
  double lost_translation_m_per_scan = 0.5;
  double lost_rotation_deg_per_scan = 10.0;
  double max_lost_translation_m = 5.0;
  double max_lost_rotation_deg = 90.0;
  // The checks of a result against its prior (localization_prior.h).
  PriorCheckOptions prior_check;

  bool IsValid(std::string* error) const;
};

// One scan's localisation: the prediction, the estimate and the
// registration of the scan onto the map from the prediction, whole.
struct LocalizationResult {
  size_t index = 0;  // 0-based position of the scan in the sequence.
  // The initial guess (the prediction) and the estimate; when the result is
  // not usable (IsSolutionUsable) the estimate is the prediction.
  Isometry3d predicted_map_from_scan = Isometry3d::Identity();
  Isometry3d map_from_scan = Isometry3d::Identity();
  double load_time_s = 0.0;  // Reading the scan (LocalizeScans).
  // The registration: verdict, fit, counts, times, scores, covariance.
  RegistrationSummary registration;

  // registration.IsSolutionUsable(): CONVERGENCE or NO_CONVERGENCE.
  bool IsSolutionUsable() const { return registration.IsSolutionUsable(); }
};

// LocalizationResult's fields (result_table.h), the registration's table
// nested: its JSON, CSV, Python and docs forms come from it.
const ResultTable& LocalizationResultTable();

class Localizer {
 public:
  // `map` is not copied and must outlive the localizer. CHECK-fails on
  // invalid options or an empty map (check options.IsValid first).
  Localizer(const LocalizerOptions& options,
            const LayeredGrid& map,
            const Isometry3d& first_map_from_scan);

  // The initial guess of the next scan, and its uncertainty.
  Isometry3d PredictNext() const;
  InitialGuessUncertainty PredictionPrior() const;

  // Registers `scan` (in its sensor frame) from PredictNext() within
  // PredictionPrior(), fills *result (its load_time_s is left as it is)
  // and updates the motion model.
  void Localize(const PointCloud& scan, LocalizationResult* result);
  // The same from a guess of the caller's (a pose file, odometry) with the
  // options' guess uncertainty.
  void LocalizeFrom(const PointCloud& scan,
                    const Isometry3d& guess,
                    LocalizationResult* result);

  size_t num_localized() const { return num_localized_; }

 private:
  LocalizerOptions options_;
  const LayeredGrid& map_;
  Isometry3d first_map_from_scan_;
  Isometry3d last_map_from_scan_ = Isometry3d::Identity();
  // Last relative motion pose_{k-2}^-1 pose_{k-1} (identity at first).
  Isometry3d last_motion_ = Isometry3d::Identity();
  size_t num_localized_ = 0;
  // Unusable scans since the last usable one (or since the start).
  size_t num_lost_ = 0;
  bool any_usable_ = false;
  // The recent prediction errors (adapt_prediction_uncertainty).
  std::deque<PredictionUncertainty> errors_;

  // The uncertainty of a prediction from its recent errors.
  void AdaptiveUncertainty(double* translation_m, double* rotation_deg) const;
  void AddPredictionError(const Isometry3d& predicted,
                          const Isometry3d& estimate);

  void LocalizeWithin(const PointCloud& scan,
                      const Isometry3d& guess,
                      const InitialGuessUncertainty& prior,
                      const PriorCheckOptions& check,
                      LocalizationResult* result);
  // The prediction's prior comes from its recent errors (not stated, not
  // the first guess's).
  bool AdaptsPrior() const;
};

// Loads scan `index` (in its sensor frame) into *scan; false with *error.
using ScanLoader =
    std::function<bool(size_t index, PointCloud* scan, std::string* error)>;

// Localises scans 0..num_scans-1 in order, loading each one when its turn
// comes into one reused cloud, each from the prediction. `progress` (may be
// null, not owned) hears of each scan once it is localised (its verdict,
// inliers, iterations and time); `results` gets every result (cleared
// first). False with *error on invalid options, an empty map or a scan that
// cannot be loaded (the results so far are kept).
bool LocalizeScans(const LocalizerOptions& options,
                   const LayeredGrid& map,
                   const Isometry3d& first_map_from_scan,
                   size_t num_scans,
                   const ScanLoader& load_scan,
                   ProgressCallback* progress,
                   std::vector<LocalizationResult>* results,
                   std::string* error);

// The same with a guess per scan: scan k starts from guesses[k]
// (LocalizeFrom), for every guess.
bool LocalizeScansFromGuesses(const LocalizerOptions& options,
                              const LayeredGrid& map,
                              const std::vector<Isometry3d>& guesses,
                              const ScanLoader& load_scan,
                              ProgressCallback* progress,
                              std::vector<LocalizationResult>* results,
                              std::string* error);

}  // namespace mlndt
