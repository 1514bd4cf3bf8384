#pragma once
// Rng — a small, seeded random number generator whose sequence is the same on every run, every
// compiler, every standard library and every IEEE-754 platform.
//
// Why not <random>: std::mt19937_64 itself is portable, but std::uniform_real_distribution,
// std::normal_distribution & co. are implementation-defined and differ between libstdc++,
// libc++ and MSVC. Genomes ([Z 8.1]) and replays must rebuild bit-for-bit, so every draw here is
// written out by hand:
//   - generator: xoshiro256** 1.0 (Blackman & Vigna), state seeded by splitmix64;
//   - uniform(): the top 53 bits scaled by 2^-53;
//   - uniform_int(): unbiased rejection sampling on 64-bit integers;
//   - normal(): Marsaglia's polar method with a logarithm built from +, -, *, / only
//     (IEEE-754 rounds those exactly, whereas std::log may differ by an ulp between libms).
//
// Not thread-safe; use one Rng per thread/creature. Not cryptographic.

#include <cstdint>

namespace ossa {

class Rng {
 public:
  /// Any seed is fine, including 0 (splitmix64 spreads it over the 256-bit state).
  explicit Rng(uint64_t seed);

  /// The next raw 64-bit output of xoshiro256**.
  uint64_t next_u64();

  /// Uniform in [0, 1), multiples of 2^-53.
  double uniform();

  /// Uniform in [lo, hi) (returns lo when lo == hi). Requires lo <= hi, both finite.
  double uniform(double lo, double hi);

  /// Uniform integer in [lo, hi_inclusive], unbiased. Requires lo <= hi_inclusive.
  int uniform_int(int lo, int hi_inclusive);

  /// Standard normal N(0, 1).
  double normal();

  /// Normal with the given mean and standard deviation (sigma >= 0).
  double normal(double mean, double sigma);

  /// True with probability p (p <= 0: never, p >= 1: always).
  bool chance(double p);

 private:
  uint64_t s_[4];
  double spare_normal_ = 0.0;  // the polar method yields pairs; the second is kept here
  bool has_spare_ = false;
};

/// Natural logarithm of x > 0 using only IEEE-754 basic operations, so the result is
/// bit-identical on every conforming platform. Relative error below 1e-15. Exposed for tests.
double deterministic_log(double x);

}  // namespace ossa
