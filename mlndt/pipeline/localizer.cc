#include "mlndt/pipeline/localizer.h"

#include <glog/logging.h>

#include <algorithm>
#include <cstdio>

#include "mlndt/common/enum_table.h"
#include "mlndt/common/pose.h"
#include "mlndt/common/timer.h"
#include "mlndt/pipeline/pipeline_option_tables.h"

namespace mlndt {

const EnumTable& MotionModelTable() {
  static const EnumTable table({
      // The default first: the choices are listed in this order.
      {static_cast<int>(MotionModel::CONSTANT_VELOCITY), "CONSTANT_VELOCITY"},
      {static_cast<int>(MotionModel::CONSTANT_POSE), "CONSTANT_POSE"},
  });
  return table;
}

const char* MotionModelToString(MotionModel model) {
  return EnumToString(MotionModelTable(), model);
}

bool StringToMotionModel(std::string value, MotionModel* model) {
  return StringToEnum(MotionModelTable(), std::move(value), model);
}

bool LocalizerOptions::IsValid(std::string* error) const {
  return registration.IsValid(error) &&
         LocalizerOwnOptionsTable().Check(*this, error) &&
         prior_check.IsValid(error) && adaptive_uncertainty.IsValid(error);
}

namespace {

// Both 0: not stated.
InitialGuessUncertainty Prior(double translation_m, double rotation_deg) {
  InitialGuessUncertainty prior;
  prior.given = translation_m > 0.0 || rotation_deg > 0.0;
  prior.translation_m = translation_m;
  prior.rotation_deg = rotation_deg;
  return prior;
}

}  // namespace

Localizer::Localizer(const LocalizerOptions& options,
                     const LayeredGrid& map,
                     const Isometry3d& first_map_from_scan)
    : options_(options), map_(map), first_map_from_scan_(first_map_from_scan) {
  std::string error;
  CHECK(options_.IsValid(&error)) << error;
  CHECK(!map_.empty()) << "the map is empty";
}

Isometry3d Localizer::PredictNext() const {
  if (num_localized_ == 0) return first_map_from_scan_;
  if (!any_usable_) return first_map_from_scan_;
  // After a gap the motion is not known: the last usable pose.
  if (num_lost_ > 0 || options_.motion_model == MotionModel::CONSTANT_POSE) {
    return last_map_from_scan_;
  }
  return last_map_from_scan_ * last_motion_;
}

InitialGuessUncertainty Localizer::PredictionPrior() const {
  const LocalizerOptions& o = options_;
  const bool from_guess = num_localized_ == 0 || !any_usable_;
  double t = from_guess ? o.guess_translation_m : o.prediction_translation_m;
  double r = from_guess ? o.guess_rotation_deg : o.prediction_rotation_deg;
  if (AdaptsPrior()) {
    AdaptiveUncertainty(&t, &r);
    if (num_lost_ == 0) return Prior(t, r);
    // After g lost scans the prediction is the last usable pose: the g + 1
    // steps' motion (the last one's) and their model errors are not
    // predicted.
    const double steps = static_cast<double>(num_lost_ + 1);
    const Eigen::AngleAxisd turn(last_motion_.linear());
    t = std::min(steps * (t + last_motion_.translation().norm()),
                 std::max(t, o.max_lost_translation_m));
    r = std::min(steps * (r + turn.angle() * kRadToDeg),
                 std::max(r, o.max_lost_rotation_deg));
    return Prior(t, std::min(r, 180.0));
  }
  // A prior not stated stays not stated over a gap.
  if (num_lost_ > 0 && (t > 0.0 || r > 0.0)) {
    const double gap = static_cast<double>(num_lost_);
    t = std::min(t + gap * o.lost_translation_m_per_scan,
                 std::max(t, o.max_lost_translation_m));
    r = std::min(r + gap * o.lost_rotation_deg_per_scan,
                 std::max(r, o.max_lost_rotation_deg));
  }
  return Prior(t, std::min(r, 180.0));
}

bool Localizer::AdaptsPrior() const {
  const LocalizerOptions& o = options_;
  return num_localized_ > 0 && any_usable_ && o.adapt_prediction_uncertainty &&
         o.prediction_translation_m == 0.0 && o.prediction_rotation_deg == 0.0;
}

void Localizer::AdaptiveUncertainty(double* translation_m,
                                    double* rotation_deg) const {
  const MotionPredictionOptions& o = options_.adaptive_uncertainty;
  const PredictionUncertainty u = OneStepUncertainty(o, errors_);
  *translation_m = std::min(u.translation_m, o.max_translation_m);
  *rotation_deg = std::min(u.rotation_deg, o.max_rotation_deg);
}

void Localizer::AddPredictionError(const Isometry3d& predicted,
                                   const Isometry3d& estimate) {
  errors_.push_back({TranslationErrorM(predicted, estimate),
                     RotationErrorRad(predicted, estimate) * kRadToDeg});
  const size_t window =
      static_cast<size_t>(options_.adaptive_uncertainty.window);
  while (errors_.size() > window) errors_.pop_front();
}

void Localizer::Localize(const PointCloud& scan, LocalizationResult* result) {
  // A prediction from the last scan, usable, measures the model's error.
  const bool from_last_scan = any_usable_ && num_lost_ == 0;
  // The fit rule (localization_prior.h) is for a prior the caller states: a
  // start that may lie where a rival minimum fits. A prior taken from the
  // prediction's own recent errors is checked without it: a scan that sees
  // beyond the map (a map of fewer scans than the run) fits less of it.
  PriorCheckOptions check = options_.prior_check;
  if (AdaptsPrior()) check.min_fit_ratio = 0.0;
  LocalizeWithin(scan, PredictNext(), PredictionPrior(), check, result);
  if (from_last_scan && result->IsSolutionUsable()) {
    AddPredictionError(result->predicted_map_from_scan, result->map_from_scan);
  }
}

void Localizer::LocalizeFrom(const PointCloud& scan,
                             const Isometry3d& guess,
                             LocalizationResult* result) {
  LocalizeWithin(
      scan,
      guess,
      Prior(options_.guess_translation_m, options_.guess_rotation_deg),
      options_.prior_check,
      result);
}

void Localizer::LocalizeWithin(const PointCloud& scan,
                               const Isometry3d& guess,
                               const InitialGuessUncertainty& prior,
                               const PriorCheckOptions& check,
                               LocalizationResult* result) {
  CHECK(result != nullptr);
  RegistrationSummary& s = result->registration;
  RegisterWithinPrior(
      check, options_.registration, map_, scan, guess, prior, &s, nullptr);

  result->index = num_localized_;
  result->predicted_map_from_scan = guess;
  result->map_from_scan = s.IsSolutionUsable() ? s.reference_from_input : guess;

  if (s.IsSolutionUsable()) {
    // The motion is known only between consecutive usable scans.
    last_motion_ = any_usable_ && num_lost_ == 0
                       ? last_map_from_scan_.inverse() * result->map_from_scan
                       : Isometry3d::Identity();
    last_map_from_scan_ = result->map_from_scan;
    any_usable_ = true;
    num_lost_ = 0;
  } else {
    // The last usable pose and the motion stay; the gap grows.
    ++num_lost_;
  }
  ++num_localized_;
}

namespace {

// The progress line of a scan: "CONVERGENCE, inliers 0.954, 52 it, 2627 ms".
std::string StatusLine(const LocalizationResult& r) {
  char line[160];
  std::snprintf(line,
                sizeof(line),
                "%s, inliers %.3f, %d it, %.0f ms",
                TerminationTypeToString(r.registration.termination_type),
                r.registration.quality.inlier_fraction,
                r.registration.num_iterations,
                r.registration.total_time_s * 1e3);
  return line;
}

// The loop of LocalizeScans and LocalizeScansFromGuesses: scan k from the
// prediction, or from (*guesses)[k] when `guesses` is not null.
bool LocalizeEach(const LocalizerOptions& options,
                  const LayeredGrid& map,
                  const Isometry3d& first_map_from_scan,
                  size_t num_scans,
                  const std::vector<Isometry3d>* guesses,
                  const ScanLoader& load_scan,
                  ProgressCallback* progress,
                  std::vector<LocalizationResult>* results,
                  std::string* error) {
  CHECK(results != nullptr);
  CHECK(error != nullptr);
  CHECK(load_scan);
  results->clear();
  if (!options.IsValid(error)) return false;
  if (map.empty()) {
    *error = "the map is empty";
    return false;
  }
  Localizer localizer(options, map, first_map_from_scan);
  PointCloud scan;
  results->reserve(num_scans);
  for (size_t k = 0; k < num_scans; ++k) {
    const double start = NowSeconds();
    if (!load_scan(k, &scan, error)) return false;
    LocalizationResult result;
    result.load_time_s = NowSeconds() - start;
    if (guesses != nullptr) {
      localizer.LocalizeFrom(scan, (*guesses)[k], &result);
    } else {
      localizer.Localize(scan, &result);
    }
    results->push_back(std::move(result));
    ReportProgress(progress,
                   {k, k + 1, num_scans, StatusLine(results->back())});
  }
  return true;
}

}  // namespace

bool LocalizeScans(const LocalizerOptions& options,
                   const LayeredGrid& map,
                   const Isometry3d& first_map_from_scan,
                   size_t num_scans,
                   const ScanLoader& load_scan,
                   ProgressCallback* progress,
                   std::vector<LocalizationResult>* results,
                   std::string* error) {
  return LocalizeEach(options,
                      map,
                      first_map_from_scan,
                      num_scans,
                      nullptr,
                      load_scan,
                      progress,
                      results,
                      error);
}

bool LocalizeScansFromGuesses(const LocalizerOptions& options,
                              const LayeredGrid& map,
                              const std::vector<Isometry3d>& guesses,
                              const ScanLoader& load_scan,
                              ProgressCallback* progress,
                              std::vector<LocalizationResult>* results,
                              std::string* error) {
  const Isometry3d first =
      guesses.empty() ? Isometry3d::Identity() : guesses.front();
  return LocalizeEach(options,
                      map,
                      first,
                      guesses.size(),
                      &guesses,
                      load_scan,
                      progress,
                      results,
                      error);
}

}  // namespace mlndt
