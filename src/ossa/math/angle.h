#pragma once
// Small angle helpers shared by the math module: a fast, portable atan2 and angle wrapping.

#include <cmath>

namespace ossa {

inline constexpr float kPi = 3.14159265358979323846f;
inline constexpr float kTwoPi = 6.28318530717958647692f;

/// atan2(y, x) in [-π, π] for finite y, x, built from +, -, *, / only: about 5× faster than
/// libm's atan2f and bit-identical on every IEEE-754 platform. Maximum error 2.6e-7 rad against
/// the exact value (about 1 float ulp for angles above 2; tested). Exactly odd in y, and
/// fast_atan2(y, -x) = π - fast_atan2(y, x) within 2 ulps. atan2(0, 0) = 0; signed zeros are
/// ignored (atan2(-0, -1) = +π).
inline float fast_atan2(float y, float x) {
  // Cephes atanf: reduce |y/x| (or |x/y|) into [0, 1], then to [-tan(π/8), tan(π/8)] with
  // atan(a) = π/4 + atan((a - 1) / (a + 1)), where a degree-9 odd polynomial is float-exact.
  const float ax = std::fabs(x);
  const float ay = std::fabs(y);
  const float mn = ax < ay ? ax : ay;
  const float mx = ax < ay ? ay : ax;
  if (mx == 0.0f) return 0.0f;
  const bool big = mn > 0.41421356237309504880f * mx;
  const float a = (big ? mn - mx : mn) / (big ? mn + mx : mx);
  const float z = a * a;
  float r = (((8.05374449538e-2f * z - 1.38776856032e-1f) * z + 1.99777106478e-1f) * z -
             3.33329491539e-1f) * z * a + a;
  r += big ? 0.25f * kPi : 0.0f;
  r = ay > ax ? 0.5f * kPi - r : r;
  r = x < 0.0f ? kPi - r : r;
  return y < 0.0f ? -r : r;
}

/// The angle a wrapped into [-π, π] (same angle modulo 2π).
inline float wrap_angle(float a) { return std::remainder(a, kTwoPi); }

}  // namespace ossa
