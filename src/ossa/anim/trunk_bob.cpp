#include "ossa/anim/trunk_bob.h"

#include <algorithm>
#include <cmath>

#include "ossa/anim/anim_math.h"
#include "ossa/anim/pentapedal.h"

namespace ossa::anim {

namespace {


// Harmonics of the series: a gallop's one bounce and its short flight need a few, the force
// kernels' spectra fall as 1/k² and the height's as 1/k⁴ beyond.
constexpr int kHarmonics = kBobHarmonics;

// The share of the ballistic estimate the girdles show, one for every gait and creature. At
// 1 the horse's trot at Froude 1 rises about 4 % of its hip height, as measured (Buchner et
// al. 2000: 53 mm), but a gallop's and a bound's trunk then jolts well over the 1.5 g the
// animator holds to outside hops; at 0.5 the trot reads about 2 % and the gallops stay under
// (issue 28; README, Gait families).
constexpr float kTrunkShare = 0.5f;

// The walk's head nod at its largest, of the hip height (half its rise and fall): ungulates
// and elephants nod twice per stride as each fore foot takes the weight, by several
// centimetres in a horse. A chosen figure, not a measured one.
constexpr float kNodOfHip = 0.025f;
// A small bird's head-bob: the share of each step the head thrusts forward (the rest it holds
// still; Frost 1978: still for most of the step).
constexpr float kHeadThrust = 0.3f;
// How far the neck's bend moves the head back and forth, of the neck's reach (base to head).
constexpr float kHeadShiftOfNeck = 0.35f;

// Complex numbers by hand: std::complex<float>'s product checks for NaN through a library
// call, and the series needs only products of unit phasors.
struct Complex {
  float re = 0.0f, im = 0.0f;
};
Complex operator*(Complex a, Complex b) { return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re}; }
Complex operator*(float s, Complex a) { return {s * a.re, s * a.im}; }
Complex operator+(Complex a, Complex b) { return {a.re + b.re, a.im + b.im}; }
Complex unit(float angle) { return {std::cos(angle), std::sin(angle)}; }

// ∫₀¹ sin(nπu)·e^{−iωu} du (n odd), given e^{−iω}.
Complex sine_transform(int n, float w, Complex e_minus_iw) {
  const float npi = static_cast<float>(n) * kPi;
  const float d = npi * npi - w * w;
  if (std::fabs(d) < 1e-4f * npi * npi) return {0.0f, -0.5f};  // ω = nπ: the limit
  return (npi / d) * Complex{1.0f + e_minus_iw.re, e_minus_iw.im};
}

}  // namespace

void footfall_series(std::span<const float> stance_start, float duty, float b, float frequency, float stride, float h, float gravity,
                     BobSeries& series) {
  series.coef.fill({0.0f, 0.0f});
  if (stance_start.empty() || !(duty > 0.0f) || !(h > 0.0f) || !(stride > 0.0f)) return;
  // s² of the double integral, with the force's swing ∝ Fr below Fr 0.5:
  // min(T², (Fr/0.5)·T²) = min(1/f², 2λ²/(g·h)).
  const float creep = 2.0f * stride * stride / (gravity * h);
  const float period2 = frequency > 0.0f ? std::min(1.0f / (frequency * frequency), creep) : creep;
  // The mean force: Σ duty·∫₀¹ f = duty·(2/π + b·2/(3π)) per leg.
  const float mean = static_cast<float>(stance_start.size()) * duty * (2.0f / kPi) * (1.0f + b / 3.0f);
  // Harmonic k's phasors are the k-th powers of the first: e^{−2πi·start} per leg and
  // e^{−2πi·duty} (the kernel's e^{−iω}); one sine and cosine each, then products.
  constexpr int kMaxLegs = 16;
  const int n = std::min(static_cast<int>(stance_start.size()), kMaxLegs);
  Complex leg_step[kMaxLegs], leg_k[kMaxLegs];
  for (int j = 0; j < n; ++j) leg_step[j] = leg_k[j] = unit(-kTwoPi * stance_start[static_cast<size_t>(j)]);
  const Complex duty_step = unit(-kTwoPi * duty);
  Complex duty_k = duty_step;
  for (int k = 1; k <= kHarmonics; ++k) {
    if (k > 1) {
      for (int j = 0; j < n; ++j) leg_k[j] = leg_k[j] * leg_step[j];
      duty_k = duty_k * duty_step;
    }
    const float w = kTwoPi * static_cast<float>(k) * duty;
    const Complex kernel = duty * (sine_transform(1, w, duty_k) + b * sine_transform(3, w, duty_k));
    Complex c;
    for (int j = 0; j < n; ++j) c = c + leg_k[j];
    // The acceleration's harmonic g·c_k/mean, integrated twice (÷ −(2πk/T)²), both signs of k.
    const float wk = kTwoPi * static_cast<float>(k);
    const Complex a = (-2.0f * kTrunkShare * period2 * gravity / (mean * wk * wk)) * (kernel * c);
    series.coef[static_cast<size_t>(k - 1)] = {a.re, a.im};
  }
}

float BobSeries::at(float phase) const {
  const Complex step = unit(kTwoPi * phase);
  Complex e = step;
  float y = 0.0f;
  for (size_t k = 0; k < coef.size(); ++k) {
    if (k > 0) e = e * step;
    y += (Complex{coef[k][0], coef[k][1]} * e).re;
  }
  return y;
}

float footfall_bob(std::span<const float> stance_start, float duty, float b, float phase, float frequency, float stride, float h,
                   float gravity) {
  BobSeries series;
  footfall_series(stance_start, duty, b, frequency, stride, h, gravity, series);
  return series.at(phase);
}

bool steady_gait(bool on_steps, bool blocked, const FootSet& feet, std::span<const uint8_t> waiting) {
  if (on_steps || blocked) return false;
  for (const FootState& f : feet.feet) {
    if (f.air) return false;
  }
  return std::none_of(waiting.begin(), waiting.end(), [](uint8_t w) { return w != 0; });
}

void trunk_bob(const AnimRig& rig, const AnimatorParams& params, const SplinePrototypes& prototypes, const FootSet& feet,
               float speed, bool steady, float dt, GaitState& gait) {
  std::vector<float>& bob = gait.girdle_bob;
  std::vector<BobSeries>& cache = gait.bob_series;
  float& weight = gait.bob_weight;
  cache.resize(rig.girdles.size());
  constexpr float kBobEaseRate = 6.0f;  // 1/s
  weight = approach(weight, steady ? 1.0f : 0.0f, std::exp(-kBobEaseRate * dt));
  bob.assign(rig.girdles.size(), 0.0f);
  gait.head_rise = gait.head_shift = gait.spine_flex = 0.0f;
  ease_pentapedal(steady, dt, gait);
  if (!gait.moving) {
    const float t = frac(gait.idle_time / params.idle_period);
    const float idle = prototype_range(PrototypeId::kIdleY).clamp(prototypes[PrototypeId::kIdleY].value(t, gait.run_factor)) * rig.hip_height;
    gait.extra_bob = idle;
    return;
  }
  const float extra = prototype_range(PrototypeId::kPelvisY).clamp(prototypes[PrototypeId::kPelvisY].value(frac(2.0f * gait.phase), gait.run_factor)) *
                      rig.hip_height;
  const float b = kWalkForceDip * (1.0f - gait.run_factor);
  const float fade = weight * std::min(1.0f, speed / std::max(0.5f * gait.walk_speed, 1e-4f));
  gait.extra_bob = extra;
  if (!(fade > 0.0f)) return;  // (bob: zeros)
  constexpr int kMaxLegsPerGirdle = 8;
  float starts[kMaxLegsPerGirdle];
  for (size_t g = 0; g < rig.girdles.size(); ++g) {
    int n = 0;
    for (int leg : rig.girdles[g].legs) {
      // A foot is in stance while its local phase φ + offset is below the duty: it lands at
      // φ = −offset.
      if (n < kMaxLegsPerGirdle) starts[n++] = frac(-gait.foot_offset[feet.foot_of_leg[leg]]);
    }
    // The series changes only when the timing does (a steady gait keeps it).
    BobSeries& series = cache[g];
    BobKey key{gait.duty, b, gait.frequency, gait.stride, n, {}};
    std::copy(starts, starts + std::min(n, 4), key.starts.begin());
    if (!(series.key == key) || n > 4) {
      footfall_series({starts, static_cast<size_t>(n)}, gait.duty, b, gait.frequency, gait.stride, rig.hip_height, params.gravity, series);
      series.key = key;
    }
    bob[g] = fade * (1.0f - gait.pentapedal) * series.at(gait.phase);  // (five supports carry the body evenly)
  }
  head_motion(rig, feet, fade, gait);
  spine_flex(rig, feet, fade, gait);
}

void spine_flex(const AnimRig& rig, const FootSet& feet, float fade, GaitState& gait) {
  if (rig.flex_count == 0 || !(gait.traits.spine_flex > 0.0f) || !(fade > 0.0f) || !(gait.fast_factor > 0.0f)) return;
  // A foot lands at φ = −offset furthest forward and lifts off at −offset + duty furthest
  // back, moving evenly between: the first harmonic of that triangle peaks (duty − ½)/2
  // cycles after the landing. Its amplitude is common to every foot and cancels below.
  const float lag = 0.5f * (gait.duty - 0.5f);
  float place[2] = {0.0f, 0.0f};
  for (size_t g = 0; g < 2; ++g) {
    const std::vector<int>& legs = rig.girdles[g].legs;
    for (int leg : legs) place[g] += std::cos(kTwoPi * (gait.phase + gait.foot_offset[feet.foot_of_leg[leg]] - lag));
    place[g] /= static_cast<float>(std::max<size_t>(legs.size(), 1));
  }
  // From −2 (fore feet back, hind feet forward: gathered) to 2 (extended).
  gait.spine_flex = -0.5f * fade * gait.fast_factor * gait.traits.spine_flex * (place[0] - place[1]);
}

void head_motion(const AnimRig& rig, const FootSet& feet, float fade, GaitState& gait) {
  if (rig.nod_bones[0] < 0 || rig.girdles.empty() || !(fade > 0.0f)) return;
  const GaitFamily family = gait.traits.family;
  if (rig.girdles.size() == 2 && (family == GaitFamily::kCursorial || family == GaitFamily::kPacer || family == GaitFamily::kGraviportal)) {
    // The nod: the fore girdle's bob, scaled to kNodOfHip at its largest (Σ|c_k| bounds the
    // series), in the walk only.
    const BobSeries& fore = gait.bob_series[0];
    float bound = 0.0f;
    for (const auto& c : fore.coef) bound += std::hypot(c[0], c[1]);
    if (bound > 0.0f) gait.head_rise = (1.0f - gait.mid_factor) * kNodOfHip * rig.hip_height * gait.girdle_bob[0] / bound;
  }
  if (rig.girdles.size() == 1 && rig.legs.size() == 2 && gait.traits.head_bob) {
    // The head-bob, once per step: the head holds its place in the world while the body
    // walks on (the head falls back relative to the body by what the body travels), then
    // thrusts forward around the next footfall, in the walk only.
    // A stride longer than the neck can take up shortens the hold: the head is then carried
    // with the body for the rest of the step. u: 0 when the hold begins; the thrust's middle
    // is the footfall.
    const float half = 0.5f * gait.stride;  // the body's travel per step
    const float travel = std::min((1.0f - kHeadThrust) * half, kHeadShiftOfNeck * glm::length(rig.nod_reach[0]));
    const float hold = travel / std::max(half, 1e-6f);
    const float step = frac(2.0f * (gait.phase + gait.foot_offset[feet.foot_of_leg[0]]));
    const float u = frac(step + hold + 0.5f * kHeadThrust);
    // The head never reaches out further than at rest (a straight neck cannot).
    float shift = 0.0f;  // carried
    if (u < hold) shift = -travel * u / hold;
    else if (u < hold + kHeadThrust) shift = travel * (smoothstep(0.0f, 1.0f, (u - hold) / kHeadThrust) - 1.0f);
    gait.head_shift = (1.0f - gait.run_factor) * fade * shift;
  }
}

}  // namespace ossa::anim
