#include "ossa/math/hermite.h"

#include "ossa/assert.h"

#include <cmath>

namespace ossa {

bool HermiteSpline::is_valid() const {
  if (keys.empty()) return false;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const HermiteKey& k = keys[i];
    if (!std::isfinite(k.t) || !std::isfinite(k.p) || !std::isfinite(k.m)) return false;
    if (i > 0 && !(keys[i - 1].t < k.t)) return false;
  }
  return true;
}

namespace {

// The evaluation itself, shared by position(), velocity() and evaluate(): in a -fPIC build a
// public member function is not inlined into another (it could be interposed), and these are
// called per creature, limb and tick. Null outputs are skipped at compile time after inlining.
inline void evaluate_spline(const std::vector<HermiteKey>& keys, float t, float* position,
                            float* velocity) {
  OSSA_ASSERT(!keys.empty(), "HermiteSpline: no keys");
  const std::size_t n = keys.size();
  if (n == 1) {
    if (position) *position = keys[0].p;
    if (velocity) *velocity = 0.0f;
    return;
  }
  // Clamp written so that NaN t lands on the first key instead of propagating.
  const float t_first = keys[0].t;
  const float t_last = keys[n - 1].t;
  t = t > t_first ? t : t_first;
  t = t < t_last ? t : t_last;

  // Branchless binary search for the last key with key.t <= t among keys[0 .. n-2]: the
  // compiler turns the select into a cmov, so random t values do not cost mispredictions.
  std::size_t i = 0;
  for (std::size_t len = n - 1; len > 1;) {
    const std::size_t half = len / 2;
    i = keys[i + half].t <= t ? i + half : i;
    len -= half;
  }
  const HermiteKey& k0 = keys[i];
  const HermiteKey& k1 = keys[i + 1];
  const float dt = k1.t - k0.t;
  const float u = (t - k0.t) / dt;
  const float m0 = k0.m * dt;  // tangents in per-segment units of u
  const float m1 = k1.m * dt;
  const float dp = k1.p - k0.p;
  if (position) {
    // Hermite basis h00 = 2u³-3u²+1, h10 = u³-2u²+u, h01 = -2u³+3u², h11 = u³-u², regrouped:
    // p = p0 + u (m0 + u (3dp - 2m0 - m1 + u (m0 + m1 - 2dp))).
    const float c2 = 3.0f * dp - 2.0f * m0 - m1;
    const float c3 = m0 + m1 - 2.0f * dp;
    *position = k0.p + u * (m0 + u * (c2 + u * c3));
  }
  if (velocity) {
    const float c2 = 3.0f * dp - 2.0f * m0 - m1;
    const float c3 = m0 + m1 - 2.0f * dp;
    *velocity = (m0 + u * (2.0f * c2 + u * 3.0f * c3)) / dt;
  }
}

}  // namespace

void HermiteSpline::evaluate(float t, float* position, float* velocity) const {
  evaluate_spline(keys, t, position, velocity);
}

float HermiteSpline::position(float t) const {
  float p = 0.0f;
  evaluate_spline(keys, t, &p, nullptr);
  return p;
}

float HermiteSpline::velocity(float t) const {
  float v = 0.0f;
  evaluate_spline(keys, t, nullptr, &v);
  return v;
}

HermiteSpline HermiteSpline::blend(const HermiteSpline& a, const HermiteSpline& b, float w) {
  OSSA_ASSERT(a.keys.size() == b.keys.size(), "HermiteSpline::blend: key counts differ");
  HermiteSpline out;
  out.keys.resize(a.keys.size());
  const float wa = 1.0f - w;
  for (std::size_t i = 0; i < a.keys.size(); ++i) {
    const HermiteKey& ka = a.keys[i];
    const HermiteKey& kb = b.keys[i];
    out.keys[i] = {wa * ka.t + w * kb.t, wa * ka.p + w * kb.p, wa * ka.m + w * kb.m};
  }
  return out;
}

}  // namespace ossa
