#include "ossa/math/bezier.h"

#include "ossa/assert.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace ossa {

glm::vec2 CubicBezier::eval(float t) const {
  const float s = 1.0f - t;
  return (s * s * s) * p[0] + (3.0f * s * s * t) * p[1] + (3.0f * s * t * t) * p[2] +
         (t * t * t) * p[3];
}

glm::vec2 CubicBezier::derivative(float t) const {
  const float s = 1.0f - t;
  return (3.0f * s * s) * (p[1] - p[0]) + (6.0f * s * t) * (p[2] - p[1]) +
         (3.0f * t * t) * (p[3] - p[2]);
}

glm::vec2 CubicBezier::second_derivative(float t) const {
  return (6.0f * (1.0f - t)) * (p[2] - 2.0f * p[1] + p[0]) + (6.0f * t) * (p[3] - 2.0f * p[2] + p[1]);
}

ArcLengthTable::ArcLengthTable(const CubicBezier& curve, int samples) : curve_(curve) {
  OSSA_ASSERT(samples >= 1, "ArcLengthTable: samples must be >= 1");
  // 5-point Gauss–Legendre nodes and weights on [-1, 1]: exact for polynomials of degree 9,
  // and |B'(t)| is smooth away from cusps, so each short interval integrates to float precision.
  static constexpr double kNodes[5] = {0.0, -0.5384693101056831, 0.5384693101056831,
                                       -0.9061798459386640, 0.9061798459386640};
  static constexpr double kWeights[5] = {0.5688888888888889, 0.4786286704993665,
                                         0.4786286704993665, 0.2369268850561891,
                                         0.2369268850561891};
  cumulative_.resize(static_cast<std::size_t>(samples) + 1);
  cumulative_[0] = 0.0f;
  double total = 0.0;  // accumulate in double so that 1000 samples do not drift
  const double h = 1.0 / samples;
  for (int i = 0; i < samples; ++i) {
    const double mid = (i + 0.5) * h;
    double seg = 0.0;
    for (int k = 0; k < 5; ++k) {
      const float t = static_cast<float>(mid + 0.5 * h * kNodes[k]);
      seg += kWeights[k] * static_cast<double>(glm::length(curve.derivative(t)));
    }
    total += 0.5 * h * seg;
    cumulative_[static_cast<std::size_t>(i) + 1] = static_cast<float>(total);
  }
}

float ArcLengthTable::t_at_length(float s) const {
  const float total = length();
  if (!(s > 0.0f) || !(total > 0.0f)) return 0.0f;  // also catches NaN s
  if (s >= total) return 1.0f;
  // First entry with cumulative >= s; s > 0 = cumulative_[0] so the index is at least 1.
  const auto it = std::lower_bound(cumulative_.begin(), cumulative_.end(), s);
  const std::size_t i = static_cast<std::size_t>(it - cumulative_.begin());
  const float s0 = cumulative_[i - 1];
  const float s1 = cumulative_[i];
  const float samples = static_cast<float>(cumulative_.size() - 1);
  // s1 > s0 here: s0 < s <= s1 by the search.
  const float frac = (s - s0) / (s1 - s0);
  const float t = (static_cast<float>(i - 1) + frac) / samples;
  return std::min(t, 1.0f);
}

float ArcLengthTable::t_at_fraction(float u) const {
  if (!(u > 0.0f)) return 0.0f;
  if (u >= 1.0f) return 1.0f;
  return t_at_length(u * length());
}

}  // namespace ossa
