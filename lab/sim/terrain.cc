#include "lab/sim/terrain.h"

#include <cmath>

namespace mlndt {
namespace sim {

Terrain::Terrain(int waves,
                 double relief_m,
                 double min_wavelength_m,
                 double max_wavelength_m,
                 SimRandom* random) {
  for (int k = 0; k < waves; ++k) {
    const double angle = random->Uniform(0.0, 2.0 * M_PI);
    const double wavelength =
        random->Uniform(min_wavelength_m, max_wavelength_m);
    Wave wave;
    wave.k = 2.0 * M_PI / wavelength *
             Eigen::Vector2d(std::cos(angle), std::sin(angle));
    wave.amplitude = relief_m / waves * random->Uniform(0.5, 1.5);
    wave.phase = random->Uniform(0.0, 2.0 * M_PI);
    waves_.push_back(wave);
  }
}

double Terrain::Height(double x, double y) const {
  double z = 0.0;
  for (const Wave& w : waves_) {
    z += w.amplitude * std::sin(w.k.x() * x + w.k.y() * y + w.phase);
  }
  return z;
}

}  // namespace sim
}  // namespace mlndt
