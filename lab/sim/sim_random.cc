#include "lab/sim/sim_random.h"

#include <glog/logging.h>

#include <cmath>

namespace mlndt {
namespace sim {
namespace {

uint64_t SplitMix64(uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

}  // namespace

uint64_t DeriveSeed(uint64_t seed, const std::string& label, uint64_t index) {
  uint64_t hash = 0xcbf29ce484222325ULL;  // FNV-1a offset basis.
  for (const char c : label) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 0x100000001b3ULL;  // FNV-1a prime.
  }
  return SplitMix64(SplitMix64(SplitMix64(seed) ^ hash) ^ index);
}

double SimRandom::Uniform() {
  return static_cast<double>(engine_() >> 11) * 0x1.0p-53;
}

double SimRandom::Uniform(double low, double high) {
  return low + (high - low) * Uniform();
}

int SimRandom::UniformInt(int low, int high) {
  CHECK_GE(high, low);
  const double span = static_cast<double>(high) - low + 1.0;
  const int value = low + static_cast<int>(std::floor(Uniform() * span));
  return value > high ? high : value;
}

double SimRandom::Gaussian() {
  // Box-Muller: u1 in (0, 1] so that log(u1) is finite.
  const double u1 = 1.0 - Uniform();
  const double u2 = Uniform();
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * M_PI * u2);
}

}  // namespace sim
}  // namespace mlndt
