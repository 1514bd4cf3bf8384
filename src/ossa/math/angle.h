#pragma once
// Small angle helpers shared by the math module: a fast, portable atan2 and angle wrapping.

#include <cmath>

namespace ossa {

inline constexpr float kPi = 3.14159265358979323846f;
inline constexpr float kTwoPi = 6.28318530717958647692f;

/// atan2(y, x) in [-π, π] built from +, -, *, / only: several times faster than libm's atan2f,
/// branch-free (random angles cost no mispredictions), and bit-identical on every IEEE-754
/// platform. Maximum error 4e-7 rad against the exact value (about 1.5 float ulps of angles
/// near π; tested). Exactly odd in y; fast_atan2(y, -x) = π - fast_atan2(y, x) within 2 ulps;
/// fast_atan2(±0, ±0) = ±0. Inputs must be finite; when both |x| and |y| are below 1e-38
/// (denormal) the result loses accuracy.
inline float fast_atan2(float y, float x) {
  // atan(a) for a = min/max in [0, 1] by the odd degree-17 polynomial of Abramowitz & Stegun
  // 4.4.49 (|error| <= 2e-8), evaluated by Estrin's scheme (short dependency chains), then the
  // octant fix-up result = offset + sign * atan(a), whose offset and sign depend only on the
  // input signs and magnitudes. Selections are written as 0/1 factors and copysign, not ?:, so
  // that the compiler emits no branches.
  const float ax = std::fabs(x);
  const float ay = std::fabs(y);
  // Two different comparisons, so that the compiler emits minss / maxss instead of one
  // comparison and a branch that selects both.
  const float mn = ay < ax ? ay : ax;
  const float mx = ax < ay ? ay : ax;
  const float den = 1.17549435e-38f < mx ? mx : 1.17549435e-38f;  // maxss: 0/0 guard
  const float swap = static_cast<float>(ay > ax);       // angle measured from the y axis
  const float negative_x = static_cast<float>(x < 0.0f);
  // (swap, negative_x) → result: (0,0) r, (1,0) π/2 - r, (0,1) π - r, (1,1) π/2 + r.
  const float offset = swap * (0.5f * kPi) + negative_x * (1.0f - swap) * kPi;
  const float sign = 1.0f - 2.0f * (swap + negative_x - 2.0f * swap * negative_x);
  const float a = mn / den;
  const float z = a * a;
  const float z2 = z * z;
  const float z4 = z2 * z2;
  const float p01 = 1.0f - 0.3333314528f * z;
  const float p23 = 0.1999355085f - 0.1420889944f * z;
  const float p45 = 0.1065626393f - 0.0752896400f * z;
  const float p67 = 0.0429096138f - 0.0161657367f * z;
  const float p07 = (p01 + p23 * z2) + (p45 + p67 * z2) * z4;
  const float r = (p07 + 0.0028662257f * (z4 * z4)) * a;
  return std::copysign(offset + sign * r, y);
}

/// The angle a wrapped into [-π, π] (same angle modulo 2π). Angles already in range (nearly
/// every call) return at once, bit-identical to what std::remainder gives them.
inline float wrap_angle(float a) { return a >= -kPi && a <= kPi ? a : std::remainder(a, kTwoPi); }

}  // namespace ossa
