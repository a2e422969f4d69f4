// Seeded random numbers that give the same values with every standard library.
//
// In: a 64-bit seed. Out: uniform doubles, integers and Gaussian doubles drawn from
// std::mt19937_64, whose output sequence the standard fixes; the std:: distributions are
// implementation-defined, so they are not used anywhere in the generators.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace curvebench {

class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}

  // Uniform in [0, 1) with 53 random bits.
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double uniform(double low, double high) { return low + (high - low) * uniform(); }
  // Uniform in {0, ..., count - 1}.
  int index(int count) { return static_cast<int>(uniform() * count); }
  // Standard normal by Box-Muller (one value per call, for simplicity of the stream).
  double gaussian() {
    const double u1 = 1.0 - uniform();  // (0, 1], so the log is finite
    const double u2 = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
  }

 private:
  std::mt19937_64 engine_;
};

// Derives independent seeds from one seed (SplitMix64), e.g. one per curve of a scene.
inline std::uint64_t derive_seed(std::uint64_t seed, std::uint64_t stream) {
  std::uint64_t z = seed + 0x9e3779b97f4a7c15ULL * (stream + 1);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

}  // namespace curvebench
