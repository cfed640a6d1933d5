#pragma once

// The simulated sensors: a scan pattern (spinning, rosette or raster) and
// how its returns are made (ranges, noise, dropouts, decimation), by name.
//
//   vlp16, hdl32, hdl64, os1_64, os1_128  spinning (spinning_sensor.h)
//   avia                                  Livox-Avia-like rosette, every 3rd
//                                         return kept (keyframe-like, a few
//                                         thousand points per scan)
//   avia_full                             the same, all ~24k rays per frame
//   narrow                                40 x 20 deg raster (raster_sensor.h)

#include <string>
#include <vector>

#include "lab/sim/raster_sensor.h"
#include "lab/sim/rosette_sensor.h"
#include "lab/sim/sensor_ray.h"
#include "lab/sim/spinning_sensor.h"

namespace mlndt {
namespace sim {

enum class ScanPattern { SPINNING, ROSETTE, RASTER };

// How a ray becomes a point.
struct ReturnOptions {
  double min_range_m = 1.0;    // Nearer hits are not returned; >= 0.
  double max_range_m = 100.0;  // Farther hits are misses; > min.
  // Gaussian range noise along the ray, sigma [m]; >= 0.
  double range_sigma_m = 0.02;
  // Probability that a hit returns nothing; in [0, 1).
  double dropout_probability = 0.02;
  // Hits with |cos(incidence)| below this (grazing) return nothing; in
  // [0, 1).
  double min_cos_incidence = 0.05;
  // Keep every k-th return, in firing order (FAST-LIO's point_filter_num);
  // >= 1.
  int keep_every = 1;

  bool IsValid(std::string* error) const;
};

struct SensorModel {
  std::string name;
  ScanPattern pattern = ScanPattern::SPINNING;
  SpinningSensorOptions spinning;
  RosetteSensorOptions rosette;
  RasterSensorOptions raster;
  ReturnOptions returns;

  bool IsValid(std::string* error) const;
};

// The names above.
std::vector<std::string> SensorNames();
// False for an unknown name.
bool MakeSensorModel(const std::string& name, SensorModel* model);

// The rays of the scan stamped `stamp_s` (absolute time [s]; only the
// rosette's pattern depends on it).
std::vector<SensorRay> SensorRays(const SensorModel& model, double stamp_s);

// Whether a direction (sensor frame) is in the pattern's field of view.
bool SensorCovers(const SensorModel& model, const Eigen::Vector3d& direction);

// The length of one scan [s].
double SweepPeriod(const SensorModel& model);

}  // namespace sim
}  // namespace mlndt
