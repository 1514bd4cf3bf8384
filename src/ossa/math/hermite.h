#pragma once
// HermiteSpline — a 1D cubic Hermite spline over normalised time, the shape of every spline
// prototype (leg swing height, pelvis bob, arm swing: DESIGN.md §7, [T 4.4.1]).
//
// Between two consecutive keys k0, k1 the curve is the cubic Hermite interpolant
//   p(t) = h00(u) p0 + h10(u) Δ m0 + h01(u) p1 + h11(u) Δ m1,   Δ = t1 - t0, u = (t - t0) / Δ,
// which matches both positions and both tangents, so the whole spline is C1 (each key has one
// tangent shared by its two segments).

#include "ossa/assert.h"

#include <cstddef>
#include <vector>

namespace ossa {

/// One key of a HermiteSpline.
struct HermiteKey {
  float t = 0.0f;  // normalised time of the key (usually in [0, 1]; any finite value works)
  float p = 0.0f;  // position (value) at t, in the unit of whatever the spline describes
  float m = 0.0f;  // tangent dp/dt at t (position units per unit of normalised time)
};

/// A C1 piecewise cubic Hermite spline. `keys` is public data (editors move keys directly);
/// it must satisfy is_valid() before position()/velocity() are called.
class HermiteSpline {
 public:
  HermiteSpline() = default;
  explicit HermiteSpline(std::vector<HermiteKey> k) : keys(std::move(k)) {}

  /// Keys sorted by strictly increasing t; at least one key.
  std::vector<HermiteKey> keys;

  /// True when there is at least one key, every value is finite and t strictly increases.
  bool is_valid() const;

  /// Position at t. t is clamped to [keys.front().t, keys.back().t]; a single key is the
  /// constant keys[0].p. No allocation; inline; the segment search scans forward up to 16
  /// keys (as fast as it gets for the short splines of the prototypes) and is O(log n) beyond.
  float position(float t) const;

  /// Velocity dp/dt at t (same clamping; at or beyond an end this is that end key's tangent).
  /// A single key has velocity 0.
  float velocity(float t) const;

  /// Position and velocity in one segment search.
  void evaluate(float t, float* position, float* velocity) const;

  /// Key-wise linear blend (1 - w) * a + w * b of t, p and m, e.g. walk → run by the
  /// walk→run factor [T 4.4.1]. a and b must have the same number of keys (asserted).
  /// For w in [0, 1] two valid splines blend into a valid one (a convex combination of two
  /// strictly increasing sequences is strictly increasing).
  static HermiteSpline blend(const HermiteSpline& a, const HermiteSpline& b, float w);
};

// ---- Inline evaluation ----------------------------------------------------------------------
// position(), velocity() and evaluate() run per creature, limb and tick: they are defined here
// so that they inline into the animator. The segment search is a forward scan: splines are short
// (the prototypes have 3 keys) and the animator's t runs steadily through the cycle, so the
// scan's branches are predicted and the CPU loads the segment's keys while the comparisons are
// still in flight. (A branchless binary search, used before, made each probe a load whose address
// waited for the previous comparison; with the call into hermite.cpp it ran 1.3x slower than a
// naive scan, tests/bench/math_bench.cpp "hermite".) Long splines take a binary search.

namespace detail {

// Up to this many keys the segment search is a forward scan, beyond it a binary search.
inline constexpr std::size_t kHermiteScanKeys = 16;

// t clamped to the keys (n >= 2), written so that NaN t lands on the first key.
inline float hermite_clamp(const std::vector<HermiteKey>& keys, float t) {
  const float t_first = keys.front().t;
  const float t_last = keys.back().t;
  t = t > t_first ? t : t_first;
  return t < t_last ? t : t_last;
}

// The cubic between k0 and k1 at t (within them). Null outputs are skipped at compile time.
inline void hermite_segment(const HermiteKey& k0, const HermiteKey& k1, float t, float* position, float* velocity) {
  const float dt = k1.t - k0.t;
  const float u = (t - k0.t) / dt;
  const float m0 = k0.m * dt;  // tangents in per-segment units of u
  const float m1 = k1.m * dt;
  const float dp = k1.p - k0.p;
  // Hermite basis h00 = 2u³-3u²+1, h10 = u³-2u²+u, h01 = -2u³+3u², h11 = u³-u², regrouped:
  // p = p0 + u (m0 + u (3dp - 2m0 - m1 + u (m0 + m1 - 2dp))).
  const float c2 = 3.0f * dp - 2.0f * m0 - m1;
  const float c3 = m0 + m1 - 2.0f * dp;
  if (position) *position = k0.p + u * (m0 + u * (c2 + u * c3));
  if (velocity) *velocity = (m0 + u * (2.0f * c2 + u * 3.0f * c3)) / dt;
}

// Splines of more than kHermiteScanKeys keys: the same evaluation with a binary search
// (hermite.cpp). Out of line and taken before anything else, so that no value of the inline
// path has to survive a call (a spilled t cost the scan a store-to-load trip per key).
void hermite_evaluate_long(const std::vector<HermiteKey>& keys, float t, float* position, float* velocity);

inline void hermite_evaluate(const std::vector<HermiteKey>& keys, float t, float* position, float* velocity) {
  OSSA_ASSERT(!keys.empty(), "HermiteSpline: no keys");
  const std::size_t n = keys.size();
  if (n == 1) {
    if (position) *position = keys[0].p;
    if (velocity) *velocity = 0.0f;
    return;
  }
  if (n > kHermiteScanKeys) {
    hermite_evaluate_long(keys, t, position, velocity);
    return;
  }
  t = hermite_clamp(keys, t);
  std::size_t i = 0;  // the last key with key.t <= t among keys[0 .. n-2]
  while (i + 2 < n && keys[i + 1].t <= t) ++i;
  hermite_segment(keys[i], keys[i + 1], t, position, velocity);
}

}  // namespace detail

inline void HermiteSpline::evaluate(float t, float* position, float* velocity) const {
  detail::hermite_evaluate(keys, t, position, velocity);
}

inline float HermiteSpline::position(float t) const {
  float p = 0.0f;
  detail::hermite_evaluate(keys, t, &p, nullptr);
  return p;
}

inline float HermiteSpline::velocity(float t) const {
  float v = 0.0f;
  detail::hermite_evaluate(keys, t, nullptr, &v);
  return v;
}

}  // namespace ossa
