#pragma once
// HermiteSpline — a 1D cubic Hermite spline over normalised time, the shape of every spline
// prototype (leg swing height, pelvis bob, arm swing: DESIGN.md §7, [T 4.4.1]).
//
// Between two consecutive keys k0, k1 the curve is the cubic Hermite interpolant
//   p(t) = h00(u) p0 + h10(u) Δ m0 + h01(u) p1 + h11(u) Δ m1,   Δ = t1 - t0, u = (t - t0) / Δ,
// which matches both positions and both tangents, so the whole spline is C1 (each key has one
// tangent shared by its two segments).

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
  /// constant keys[0].p. O(log n) segment search, no allocation.
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

}  // namespace ossa
