#include "ossa/anim/trunk_bob.h"

#include <algorithm>
#include <cmath>
#include <complex>

#include "ossa/anim/anim_math.h"

namespace ossa::anim {

namespace {

using Complex = std::complex<float>;

// Harmonics of the series: a gallop's one bounce and its short flight need a few, the force
// kernels' spectra fall as 1/k² and the height's as 1/k⁴ beyond.
constexpr int kHarmonics = 6;

// The part of the centre of mass's vertical excursion the girdles show. The girdles ride on
// legs that shorten under load and a spine that gives: the stride clock's periods (Alexander's
// λ ≈ 2.3·h·Fr^0.3, longer strides than a horse's at a trot) make the ballistic estimate
// about 1.6 times the horse's measured trot (Buchner et al. 2000: 53 mm, 4 % of the hip
// height, at about Fr 1); one share for every gait and creature.
constexpr float kTrunkShare = 0.5f;

// ∫₀¹ sin(nπu)·e^{−iωu} du (n odd).
Complex sine_transform(int n, float w) {
  const float npi = static_cast<float>(n) * kPi;
  const float d = npi * npi - w * w;
  if (std::fabs(d) < 1e-4f * npi * npi) return {0.0f, -0.5f};  // ω = nπ: the limit
  return npi * (1.0f + std::polar(1.0f, -w)) / d;
}

}  // namespace

float footfall_bob(std::span<const float> stance_start, float duty, float b, float phase, float frequency, float stride, float h,
                   float gravity) {
  if (stance_start.empty() || !(duty > 0.0f) || !(h > 0.0f) || !(stride > 0.0f)) return 0.0f;
  // s² of the double integral, with the force's swing ∝ Fr below Fr 0.5:
  // min(T², (Fr/0.5)·T²) = min(1/f², 2λ²/(g·h)).
  const float creep = 2.0f * stride * stride / (gravity * h);
  const float period2 = frequency > 0.0f ? std::min(1.0f / (frequency * frequency), creep) : creep;
  // The mean force: Σ duty·∫₀¹ f = duty·(2/π + b·2/(3π)) per leg.
  const float mean = static_cast<float>(stance_start.size()) * duty * (2.0f / kPi) * (1.0f + b / 3.0f);
  float y = 0.0f;
  for (int k = 1; k <= kHarmonics; ++k) {
    const float w = kTwoPi * static_cast<float>(k) * duty;
    const Complex kernel = duty * (sine_transform(1, w) + b * sine_transform(3, w));
    Complex c{0.0f, 0.0f};
    for (float start : stance_start) c += std::polar(1.0f, -kTwoPi * static_cast<float>(k) * start);
    // The acceleration's harmonic g·c_k/mean, integrated twice: ÷ −(2πk/T)².
    const Complex a = gravity * kernel * c / mean;
    const float wk = kTwoPi * static_cast<float>(k);
    y -= 2.0f * (a * std::polar(1.0f, kTwoPi * static_cast<float>(k) * phase)).real() / (wk * wk);
  }
  return kTrunkShare * y * period2;
}

float trunk_bob(const AnimRig& rig, const AnimatorParams& params, const SplinePrototypes& prototypes, const GaitState& gait,
               const FootSet& feet, float speed, bool steady, float dt, std::vector<float>& bob, float& weight) {
  constexpr float kBobEaseRate = 6.0f;  // 1/s
  weight = approach(weight, steady ? 1.0f : 0.0f, std::exp(-kBobEaseRate * dt));
  bob.assign(rig.girdles.size(), 0.0f);
  if (!gait.moving) {
    const float t = frac(gait.idle_time / params.idle_period);
    const float idle = prototype_range(PrototypeId::kIdleY).clamp(prototypes[PrototypeId::kIdleY].value(t, gait.run_factor)) * rig.hip_height;
    return idle;
  }
  const float extra = prototype_range(PrototypeId::kPelvisY).clamp(prototypes[PrototypeId::kPelvisY].value(frac(2.0f * gait.phase), gait.run_factor)) *
                      rig.hip_height;
  const float b = kWalkForceDip * (1.0f - gait.run_factor);
  const float fade = weight * std::min(1.0f, speed / std::max(0.5f * walk_speed(rig, params), 1e-4f));
  constexpr int kMaxLegsPerGirdle = 8;
  float starts[kMaxLegsPerGirdle];
  for (size_t g = 0; g < rig.girdles.size(); ++g) {
    int n = 0;
    for (int leg : rig.girdles[g].legs) {
      // A foot is in stance while its local phase φ + offset is below the duty: it lands at
      // φ = −offset.
      if (n < kMaxLegsPerGirdle) starts[n++] = frac(-gait.foot_offset[feet.foot_of_leg[leg]]);
    }
    bob[g] = fade * footfall_bob({starts, static_cast<size_t>(n)}, gait.duty, b, gait.phase, gait.frequency, gait.stride,
                                  rig.hip_height, params.gravity);
  }
  return extra;
}

}  // namespace ossa::anim
