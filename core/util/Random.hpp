#pragma once
// Deterministic random numbers: the same seed gives the same stream on every platform and
// compiler (std::uniform_real_distribution is implementation-defined, so we do not use it).
#include <cstdint>
#include <random>

namespace vorodg {

class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}

  /// 64 uniform random bits.
  std::uint64_t bits() { return engine_(); }
  /// Poisson-distributed count with mean -log(exp_minus_mean) (Knuth's product method; for
  /// small means).
  int poisson(double exp_minus_mean) {
    int k = 0;
    for (double p = uniform(); p > exp_minus_mean; p *= uniform()) ++k;
    return k;
  }
  /// Uniform double in [0, 1) with 53 random bits.
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  /// Uniform double in [a, b).
  double uniform(double a, double b) { return a + (b - a) * uniform(); }
  /// Uniform integer in [0, n), n > 0 (multiply-shift, no modulo bias worth speaking of).
  std::size_t index(std::size_t n) {
    __extension__ using Wide = unsigned __int128;
    return static_cast<std::size_t>((static_cast<Wide>(engine_()) * n) >> 64);
  }

 private:
  std::mt19937_64 engine_;
};

/// Seed of item i of a family derived from a base seed: a pure function (SplitMix64 finalizer),
/// so realization i gets the same mesh whatever order or thread computes it.
inline std::uint64_t derive_seed(std::uint64_t base, std::uint64_t i) {
  std::uint64_t z = base + 0x9E3779B97F4A7C15ull * (i + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

}  // namespace vorodg
