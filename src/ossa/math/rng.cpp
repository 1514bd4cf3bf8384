#include "ossa/math/rng.h"

#include "ossa/assert.h"

#include <cmath>

namespace ossa {

namespace {

// splitmix64 (Steele, Lea, Flood 2014): the seeding generator recommended for xoshiro.
uint64_t splitmix64(uint64_t& x) {
  uint64_t z = (x += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

inline uint64_t rotl(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

}  // namespace

Rng::Rng(uint64_t seed) {
  uint64_t x = seed;
  for (uint64_t& s : s_) s = splitmix64(x);
  // splitmix64 is a bijection of its counter, so four consecutive outputs are never all zero.
}

uint64_t Rng::next_u64() {
  // xoshiro256** 1.0, reference implementation by Blackman & Vigna (public domain).
  const uint64_t result = rotl(s_[1] * 5, 7) * 9;
  const uint64_t t = s_[1] << 17;
  s_[2] ^= s_[0];
  s_[3] ^= s_[1];
  s_[1] ^= s_[2];
  s_[0] ^= s_[3];
  s_[2] ^= t;
  s_[3] = rotl(s_[3], 45);
  return result;
}

double Rng::uniform() { return static_cast<double>(next_u64() >> 11) * 0x1.0p-53; }

double Rng::uniform(double lo, double hi) {
  OSSA_ASSERT(lo <= hi, "Rng::uniform: lo must not exceed hi");
  const double v = lo + (hi - lo) * uniform();
  // Rounding can land exactly on hi for wide ranges; keep the interval half-open.
  return v < hi ? v : lo;
}

int Rng::uniform_int(int lo, int hi_inclusive) {
  OSSA_ASSERT(lo <= hi_inclusive, "Rng::uniform_int: lo must not exceed hi_inclusive");
  const uint64_t range =
      static_cast<uint64_t>(static_cast<int64_t>(hi_inclusive) - static_cast<int64_t>(lo)) + 1;
  // Reject the lowest (2^64 mod range) values so that every residue is equally likely.
  const uint64_t threshold = (0 - range) % range;
  uint64_t r = next_u64();
  while (r < threshold) r = next_u64();
  return static_cast<int>(static_cast<int64_t>(lo) + static_cast<int64_t>(r % range));
}

double Rng::normal() {
  if (has_spare_) {
    has_spare_ = false;
    return spare_normal_;
  }
  // Marsaglia polar method: a uniform point in the unit disc gives two independent normals.
  double u = 0.0, v = 0.0, s = 0.0;
  do {
    u = 2.0 * uniform() - 1.0;
    v = 2.0 * uniform() - 1.0;
    s = u * u + v * v;
  } while (s >= 1.0 || s == 0.0);
  const double f = std::sqrt(-2.0 * deterministic_log(s) / s);  // sqrt is exactly rounded
  spare_normal_ = v * f;
  has_spare_ = true;
  return u * f;
}

double Rng::normal(double mean, double sigma) { return mean + sigma * normal(); }

bool Rng::chance(double p) { return uniform() < p; }

double deterministic_log(double x) {
  if (!(x > 0.0)) return x == 0.0 ? -HUGE_VAL : std::nan("");
  if (std::isinf(x)) return x;
  // x = m * 2^e exactly; move m into [sqrt(1/2), sqrt(2)) so that s below stays small.
  int e = 0;
  double m = std::frexp(x, &e);
  if (m < 0.70710678118654752440) {
    m *= 2.0;
    --e;
  }
  // ln(m) = 2 atanh(s) = 2 (s + s^3/3 + s^5/5 + ...), s = (m - 1) / (m + 1), |s| < 0.1716;
  // eleven terms take the truncation error below 1e-18.
  const double s = (m - 1.0) / (m + 1.0);
  const double z = s * s;
  double poly = 1.0 / 23.0;
  for (int k = 10; k >= 0; --k) poly = poly * z + 1.0 / static_cast<double>(2 * k + 1);
  // ln 2 split as in fdlibm so that e * kLn2Hi is exact.
  constexpr double kLn2Hi = 6.93147180369123816490e-01;
  constexpr double kLn2Lo = 1.90821492927058770002e-10;
  const double fe = static_cast<double>(e);
  return fe * kLn2Hi + (fe * kLn2Lo + 2.0 * s * poly);
}

}  // namespace ossa
