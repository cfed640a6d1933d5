#pragma once

// Smooth random terrain: a sum of a few sinusoids with random directions,
// wavelengths and phases, for the outdoor scenes' ground.

#include <Eigen/Core>
#include <vector>

#include "lab/sim/sim_random.h"

namespace mlndt {
namespace sim {

class Terrain {
 public:
  // `waves` sinusoids of wavelengths in [min_wavelength_m,
  // max_wavelength_m], total amplitude about `relief_m`.
  Terrain(int waves,
          double relief_m,
          double min_wavelength_m,
          double max_wavelength_m,
          SimRandom* random);

  double Height(double x, double y) const;

 private:
  struct Wave {
    Eigen::Vector2d k;  // Wave vector [rad/m].
    double amplitude = 0.0;
    double phase = 0.0;
  };
  std::vector<Wave> waves_;
};

}  // namespace sim
}  // namespace mlndt
