#pragma once
// Small numeric helpers the animator's stages share: phases on the unit circle, eases,
// exponential smoothing, 2D rotation. Header-only; no state.

#include <algorithm>
#include <cmath>

#include <glm/vec2.hpp>

#include "ossa/math/angle.h"
#include "ossa/skeleton/pose.h"

namespace ossa::anim {

// x - floor(x) in [0, 1), without a library call for the phases' range.
inline float frac(float x) {
  if (!(std::fabs(x) < 1e6f)) return x - std::floor(x);
  const float f = x - static_cast<float>(static_cast<int>(x));
  return f < 0.0f ? f + 1.0f : f;
}
inline float smoothstep(float a, float b, float x) {
  const float t = std::clamp((x - a) / (b - a), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}
// Signed shortest difference b - a of two phases, in (-0.5, 0.5].
inline float phase_diff(float a, float b) {
  float d = frac(b - a);
  return d > 0.5f ? d - 1.0f : d;
}
inline float circular_lerp(float a, float b, float t) { return frac(a + t * phase_diff(a, b)); }
// Did the phase, moving from prev to now (forward by less than half a cycle), pass x?
inline bool crossed(float prev, float now, float x) {
  const float d = phase_diff(prev, now);
  if (d <= 0.0f) return false;
  const float to_x = frac(x - prev);
  return to_x > 0.0f && to_x <= d;
}
// Below this a decaying quantity is zero: left alone, exponential decays run into denormal
// floats after a few thousand ticks, and arithmetic on those is a hundred times slower.
constexpr float kNegligible = 1e-12f;
inline float flush(float x) { return std::fabs(x) < kNegligible ? 0.0f : x; }
// Exponential approach: value moves towards target, keeping a fraction `keep` = exp(-rate·dt).
inline float approach(float value, float target, float keep) { return target + flush((value - target) * keep); }
inline glm::vec2 rotate(glm::vec2 v, float a) {
  const float c = std::cos(a), s = std::sin(a);
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}
inline float bone_angle(const Mat2x3& m) { return std::atan2(m.m[1], m.m[0]); }
// How far across a circle of radius r reaches at an offset h from its centre: a leg of reach r
// whose foot lies h below its joint reaches this far forward or back (0 beyond the circle).
inline float reach_across(float r, float h) { return std::sqrt(std::max(r * r - h * h, 0.0f)); }
// Bisection over [lo, hi] in n halvings: each middle m goes to lo when low_side(m) (the side
// that still fails), else to hi. The caller reads lo and hi after.
template <class LowSide>
inline void bisect(float& lo, float& hi, int n, LowSide&& low_side) {
  for (int k = 0; k < n; ++k) {
    const float mid = 0.5f * (lo + hi);
    (low_side(mid) ? lo : hi) = mid;
  }
}
// The swing's clearance bump over its progress s in [0, 1]: 0 at both ends, 1 mid-swing.
inline float bump(float s) { return std::pow(std::max(0.0f, std::sin(kPi * s)), 0.7f); }

}  // namespace ossa::anim
