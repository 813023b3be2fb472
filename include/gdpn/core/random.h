#pragma once
/// \file
/// The model's random generator: xoshiro256** seeded through splitmix64, with its own
/// distributions, so one seed gives the same numbers on every standard library.

#include <array>
#include <cstdint>

namespace gdpn::core {

/// A portable, seedable generator. Every random draw in a run comes from one of these.
class Random {
 public:
  /// Seeds the generator; the same seed always gives the same sequence.
  explicit Random(std::uint64_t seed = 1) { reseed(seed); }

  /// Restarts the sequence from `seed`.
  void reseed(std::uint64_t seed);
  /// The next raw 64-bit output.
  std::uint64_t next();
  /// A double uniform in [0, 1), 53 random bits.
  double uniform01();
  /// A double uniform in [lo, hi).
  double uniform(double lo, double hi);
  /// A normal variate with mean `mean` and standard deviation `sd` (Marsaglia's polar method).
  double normal(double mean, double sd);
  /// An exponential variate with the given mean (not rate).
  double exponential(double mean);
  /// An integer uniform in [0, n), without modulo bias; n must be positive.
  std::uint64_t below(std::uint64_t n);

 private:
  std::array<std::uint64_t, 4> s_{};
  double spare_ = 0.0;
  bool has_spare_ = false;
};

}  // namespace gdpn::core
