#pragma once

// The simulator's random numbers: one generator per purpose, each seeded
// from the data set's seed and a label, so that a change in how many
// numbers one part draws never changes what another part draws. The
// generator is std::mt19937_64 (its output is fixed by the C++ standard)
// and the distributions are written here (std::normal_distribution's output
// is not fixed), so a seed gives the same numbers with any standard library.

#include <cstdint>
#include <random>
#include <string>

namespace mlndt {
namespace sim {

// A 64-bit seed from (seed, label, index): FNV-1a over the label, mixed
// with the seed and index by SplitMix64's finaliser.
uint64_t DeriveSeed(uint64_t seed, const std::string& label, uint64_t index);

class SimRandom {
 public:
  explicit SimRandom(uint64_t seed) : engine_(seed) {}
  SimRandom(uint64_t seed, const std::string& label, uint64_t index = 0)
      : engine_(DeriveSeed(seed, label, index)) {}

  // Uniform in [0, 1), from the top 53 bits of one draw.
  double Uniform();
  // Uniform in [low, high).
  double Uniform(double low, double high);
  // Uniform integer in [low, high] (high >= low).
  int UniformInt(int low, int high);
  // True with probability p.
  bool Bernoulli(double p) { return Uniform() < p; }
  // Standard normal (Box-Muller, one value per two uniforms).
  double Gaussian();
  // -1 or +1 with equal probability.
  double Sign() { return Uniform() < 0.5 ? -1.0 : 1.0; }

 private:
  std::mt19937_64 engine_;
};

}  // namespace sim
}  // namespace mlndt
