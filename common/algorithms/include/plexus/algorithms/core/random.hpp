// Reproducible random numbers for sensor and noise models.
//
// Every family draws its noise through this helper so that a seed gives the same
// numbers on every platform and standard library: std::mt19937_64 is fully
// specified by the C++ standard, std::normal_distribution is not (libstdc++ and
// libc++ produce different sequences). The transforms below are fixed here:
//   uniform01(): the top 53 bits of one engine draw, mapped to (0, 1];
//   normal():    Box-Muller on two uniform01() draws, cosine branch only,
//                so every normal() consumes exactly two engine draws (no cache,
//                no hidden state besides the engine).
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <utility>

namespace plexus::algorithms {

class Rng {
 public:
  explicit Rng(std::uint64_t seed = 0) : engine_(seed) {}

  /// Uniform on (0, 1], 53-bit resolution; never returns 0 (safe under log()).
  double uniform01() {
    constexpr double kScale = 1.0 / 9007199254740992.0;  // 2^-53
    return static_cast<double>((engine_() >> 11) + 1) * kScale;
  }

  /// Uniform on (lo, hi].
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform01(); }

  /// Standard normal N(0, 1) by Box-Muller (cosine branch); two engine draws.
  double normal() {
    const double u1 = uniform01();
    const double u2 = uniform01();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
  }

  /// N(mean, sigma^2).
  double normal(double mean, double sigma) { return mean + sigma * normal(); }

  /// Two independent standard normals from the same two draws (cosine and sine branches).
  std::pair<double, double> normal_pair() {
    const double u1 = uniform01();
    const double u2 = uniform01();
    const double r = std::sqrt(-2.0 * std::log(u1));
    const double a = 2.0 * std::numbers::pi * u2;
    return {r * std::cos(a), r * std::sin(a)};
  }

  /// The underlying engine, for callers that need raw 64-bit draws.
  std::mt19937_64& engine() { return engine_; }

 private:
  std::mt19937_64 engine_;
};

}  // namespace plexus::algorithms
