#include "lab/sim/sensor_model.h"

namespace mlndt {
namespace sim {
namespace {

SensorModel Spinning(const std::string& name,
                     const SpinningSensorOptions& options,
                     double max_range_m,
                     double range_sigma_m) {
  SensorModel model;
  model.name = name;
  model.pattern = ScanPattern::SPINNING;
  model.spinning = options;
  model.returns.min_range_m = 1.0;
  model.returns.max_range_m = max_range_m;
  model.returns.range_sigma_m = range_sigma_m;
  return model;
}

SensorModel Avia(const std::string& name, int keep_every) {
  SensorModel model;
  model.name = name;
  model.pattern = ScanPattern::ROSETTE;
  model.returns.min_range_m = 0.5;
  model.returns.max_range_m = 190.0;
  model.returns.range_sigma_m = 0.02;
  model.returns.keep_every = keep_every;
  return model;
}

}  // namespace

bool ReturnOptions::IsValid(std::string* error) const {
  if (!(min_range_m >= 0.0 && max_range_m > min_range_m &&
        max_range_m <= 1e4)) {
    *error = "returns: need 0 <= min_range_m < max_range_m <= 1e4";
    return false;
  }
  if (!(range_sigma_m >= 0.0 && range_sigma_m <= 10.0)) {
    *error = "returns: range_sigma_m must be in [0, 10]";
    return false;
  }
  if (!(dropout_probability >= 0.0 && dropout_probability < 1.0) ||
      !(min_cos_incidence >= 0.0 && min_cos_incidence < 1.0)) {
    *error =
        "returns: dropout_probability and min_cos_incidence must be in "
        "[0, 1)";
    return false;
  }
  if (keep_every < 1) {
    *error = "returns: keep_every must be >= 1";
    return false;
  }
  return true;
}

bool SensorModel::IsValid(std::string* error) const {
  if (!returns.IsValid(error)) return false;
  switch (pattern) {
    case ScanPattern::SPINNING:
      return spinning.IsValid(error);
    case ScanPattern::ROSETTE:
      return rosette.IsValid(error);
    case ScanPattern::RASTER:
      return raster.IsValid(error);
  }
  return false;
}

std::vector<std::string> SensorNames() {
  return {"vlp16",
          "hdl32",
          "hdl64",
          "os1_64",
          "os1_128",
          "avia",
          "avia_full",
          "narrow"};
}

bool MakeSensorModel(const std::string& name, SensorModel* model) {
  if (name == "vlp16") {
    *model = Spinning(name, Vlp16Options(), 100.0, 0.03);
  } else if (name == "hdl32") {
    *model = Spinning(name, Hdl32Options(), 100.0, 0.02);
  } else if (name == "hdl64") {
    *model = Spinning(name, Hdl64Options(), 120.0, 0.02);
  } else if (name == "os1_64") {
    *model = Spinning(name, Os1_64Options(), 120.0, 0.015);
  } else if (name == "os1_128") {
    *model = Spinning(name, Os1_128Options(), 120.0, 0.015);
  } else if (name == "avia") {
    *model = Avia(name, 3);
  } else if (name == "avia_full") {
    *model = Avia(name, 1);
  } else if (name == "narrow") {
    model->name = name;
    model->pattern = ScanPattern::RASTER;
    model->raster = RasterSensorOptions();
    model->returns = ReturnOptions();
    model->returns.min_range_m = 0.5;
    model->returns.max_range_m = 150.0;
    model->returns.range_sigma_m = 0.02;
  } else {
    return false;
  }
  return true;
}

std::vector<SensorRay> SensorRays(const SensorModel& model, double stamp_s) {
  switch (model.pattern) {
    case ScanPattern::SPINNING:
      return SpinningRays(model.spinning);
    case ScanPattern::ROSETTE:
      return RosetteRays(model.rosette, stamp_s);
    case ScanPattern::RASTER:
      return RasterRays(model.raster);
  }
  return {};
}

bool SensorCovers(const SensorModel& model, const Eigen::Vector3d& direction) {
  switch (model.pattern) {
    case ScanPattern::SPINNING:
      return SpinningCovers(model.spinning, direction);
    case ScanPattern::ROSETTE:
      return RosetteCovers(model.rosette, direction);
    case ScanPattern::RASTER:
      return RasterCovers(model.raster, direction);
  }
  return false;
}

double SweepPeriod(const SensorModel& model) {
  switch (model.pattern) {
    case ScanPattern::SPINNING:
      return model.spinning.sweep_period_s;
    case ScanPattern::ROSETTE:
      return model.rosette.frame_period_s;
    case ScanPattern::RASTER:
      return model.raster.frame_period_s;
  }
  return 0.0;
}

}  // namespace sim
}  // namespace mlndt
