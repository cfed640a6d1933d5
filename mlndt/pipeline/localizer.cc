#include "mlndt/pipeline/localizer.h"

#include <glog/logging.h>

#include "mlndt/common/enum_table.h"
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
         LocalizerOwnOptionsTable().Check(*this, error);
}

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
  if (options_.motion_model == MotionModel::CONSTANT_POSE) {
    return last_map_from_scan_;
  }
  return last_map_from_scan_ * last_motion_;
}

void Localizer::Localize(const PointCloud& scan, LocalizationResult* result) {
  CHECK(result != nullptr);
  RegistrationSummary& s = result->registration;
  const Isometry3d predicted = PredictNext();
  Register(options_.registration, map_, scan, predicted, &s);

  result->index = num_localized_;
  result->predicted_map_from_scan = predicted;
  result->map_from_scan =
      s.IsSolutionUsable() ? s.reference_from_input : predicted;

  if (s.IsSolutionUsable()) {
    if (num_localized_ > 0) {
      last_motion_ = last_map_from_scan_.inverse() * result->map_from_scan;
    }
    last_map_from_scan_ = result->map_from_scan;
  } else {
    // Dead reckoning: the prediction stands in for the pose, the motion is
    // kept.
    last_map_from_scan_ = predicted;
  }
  ++num_localized_;
}

bool LocalizeScans(const LocalizerOptions& options,
                   const LayeredGrid& map,
                   const Isometry3d& first_map_from_scan,
                   size_t num_scans,
                   const ScanLoader& load_scan,
                   const LocalizationCallback& on_result,
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
    localizer.Localize(scan, &result);
    results->push_back(std::move(result));
    if (on_result) on_result(results->back());
  }
  return true;
}

}  // namespace mlndt
