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

namespace detail {

void hermite_evaluate_long(const std::vector<HermiteKey>& keys, float t, float* position, float* velocity) {
  t = hermite_clamp(keys, t);
  // The last key with key.t <= t among keys[0 .. n-2]: keys[lo].t <= t, and t < keys[hi].t or
  // hi = n - 1.
  std::size_t lo = 0, hi = keys.size() - 1;
  while (hi - lo > 1) {
    const std::size_t mid = lo + (hi - lo) / 2;
    if (keys[mid].t <= t) lo = mid;
    else hi = mid;
  }
  hermite_segment(keys[lo], keys[lo + 1], t, position, velocity);
}

}  // namespace detail

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
