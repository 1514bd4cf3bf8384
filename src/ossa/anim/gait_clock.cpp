#include "ossa/anim/gait_clock.h"

#include <algorithm>
#include <cmath>

#include "ossa/anim/anim_math.h"

namespace ossa {

namespace anim {

namespace {

// The gait blends ramp between these fractions of their Froude numbers (the middle gait
// blends over ±30 %, the fast one over ±15 %).
constexpr float kTrotBandLow = 0.7f, kTrotBandHigh = 1.3f;
constexpr float kGallopBandLow = 0.85f, kGallopBandHigh = 1.15f;
// Alexander's relation λ ≈ 2.3·h·Fr^0.3 [DESIGN.md §7].
constexpr float kStrideOfHip = 2.3f;
constexpr float kStrideFroudeExponent = 0.3f;
// A stance foot half a stance ahead or behind its girdle stays within this fraction of the
// leg's horizontal reach.
constexpr float kStanceReachUse = 0.9f;
// The stride is at least this many hip heights.
constexpr float kMinStrideOfHip = 0.25f;
// A duty floor keeps at least this much over half a cycle: a floor of 0.5 means two feet down
// at some moments but never none, also when a foot lands a tick late.
constexpr float kFloorMargin = 0.05f;

// The family's traits, cached per family.
const GaitFamilyTraits& traits_of(const AnimRig& rig, GaitFamily family, GaitState& gait) {
  if (gait.traits_family != family) {
    gait.traits = gait_family_traits(family, rig);
    gait.traits_family = family;
  }
  return gait.traits;
}

constexpr float kPentapedalStrideCut = 0.4f;

float walk_froude(const GaitFamilyTraits& t) { return std::min(0.5f, 0.4f * t.top_froude); }

}  // namespace

float walk_speed(const AnimRig& rig, const AnimatorParams& params) {
  return std::sqrt(walk_froude(gait_family_traits(gait_family(rig, params), rig)) * params.gravity * rig.hip_height);
}
float run_speed(const AnimRig& rig, const AnimatorParams& params) {
  return std::sqrt(gait_family_traits(gait_family(rig, params), rig).top_froude * params.gravity * rig.hip_height);
}

GaitBands gait_bands(const AnimRig& rig, const AnimatorParams& params) {
  const GaitFamilyTraits t = gait_family_traits(gait_family(rig, params), rig);
  auto speed = [&](float froude) {
    return froude * params.gait_froude_scale > t.top_froude ? 0.0f : std::sqrt(std::max(froude * params.gait_froude_scale, 0.0f) * params.gravity * rig.hip_height);
  };
  GaitBands b;
  b.family = t.family;
  b.gaits = t.gaits;
  if (t.gaits[1] != t.gaits[0]) b.mid = rig.girdles.size() == 1 && t.family != GaitFamily::kHopper
                                            ? speed(0.5f * (params.run_froude_start + params.run_froude_end) / params.gait_froude_scale)
                                            : speed(t.mid_froude);
  if (t.gaits[2] != t.gaits[1]) b.fast = speed(t.fast_froude);
  b.full_run = run_speed(rig, params);
  return b;
}

void update_gait(const AnimRig& rig, const AnimatorParams& params, float speed, bool on_steps, float keep_run, float keep_gait,
                 GaitState& gait) {
  const GaitFamilyTraits& t = traits_of(rig, gait_family(rig, params), gait);
  gait.walk_speed = std::sqrt(walk_froude(t) * params.gravity * rig.hip_height);
  gait.run_speed = std::sqrt(t.top_froude * params.gravity * rig.hip_height);
  gait.froude = speed * speed / (params.gravity * rig.hip_height);
  gait.run_factor = approach(gait.run_factor, smoothstep(params.run_froude_start, params.run_froude_end, gait.froude), keep_run);
  const float scale = params.gait_froude_scale;
  float mid = smoothstep(kTrotBandLow * t.mid_froude * scale, kTrotBandHigh * t.mid_froude * scale, gait.froude);
  float fast = on_steps ? 0.0f : smoothstep(kGallopBandLow * t.fast_froude * scale, kGallopBandHigh * t.fast_froude * scale, gait.froude);
  if (params.gait_override != GaitOverride::kAuto) {
    mid = params.gait_override == GaitOverride::kWalk ? 0.0f : 1.0f;
    fast = params.gait_override == GaitOverride::kGallop ? 1.0f : 0.0f;
  }
  gait.mid_factor = approach(gait.mid_factor, mid, keep_gait);
  gait.fast_factor = approach(gait.fast_factor, fast, keep_gait);
  gait.duty = params.duty_walk + (params.duty_run - params.duty_walk) * gait.run_factor;
  // Families that keep a foot down (graviportal, heavy bipeds), and a bird's grounded run.
  float floor = t.duty_floor;
  if (gait.froude < t.aerial_froude * scale) floor = std::max(floor, 0.5f);
  if (floor > 0.0f) gait.duty = std::max(gait.duty, floor + kFloorMargin);
  // Stride: Alexander's relation, limited so that a stance foot half a stance ahead or
  // behind its girdle stays within reach.
  if (gait.froude != gait.stride_froude) {
    gait.stride_froude = gait.froude;
    gait.stride_pow = std::pow(std::max(gait.froude, 1e-4f), kStrideFroudeExponent);
  }
  // (The pentapedal walk's hind feet swing past the hands on folded legs: shorter strides.)
  const float stride = kStrideOfHip * rig.hip_height * gait.stride_pow * params.step_distance_multiplier *
                       (1.0f - kPentapedalStrideCut * gait.pentapedal);
  if (params.stance_height != gait.reach_stance_height) {
    gait.reach_stance_height = params.stance_height;
    gait.min_reach_x = 1e30f;
    for (const RigLeg& leg : rig.legs) {
      const float h = rig.girdles[leg.girdle].rest_height * params.stance_height;
      gait.min_reach_x = std::min(gait.min_reach_x, reach_across(leg.contact_reach, h));
    }
  }
  // The shortest reach limits most: x ↦ 1.8 x / duty is monotonic also in float arithmetic.
  const float max_stride = std::min(1e30f, 2.0f * kStanceReachUse * gait.min_reach_x / std::max(gait.duty, 0.2f));
  const float min_stride = kMinStrideOfHip * rig.hip_height;
  gait.stride = std::clamp(stride, min_stride, std::max(max_stride, min_stride));
  gait.frequency = speed > 0.0f ? speed / gait.stride : 0.0f;

  if (rig.legs.empty()) {
    gait.gait = speed > 0.0f ? Gait::kCrawl : Gait::kIdle;
  } else if (speed <= 0.0f) {
    gait.gait = Gait::kIdle;
  } else if (rig.girdles.size() == 1 && t.family != GaitFamily::kHopper) {
    // One pair: the walk→run blend names the middle gait (the run, a bird's grounded run).
    gait.gait = gait.fast_factor > 0.5f ? t.gaits[2] : gait.run_factor > 0.5f ? t.gaits[1] : t.gaits[0];
  } else {
    gait.gait = gait.fast_factor > 0.5f ? t.gaits[2] : gait.mid_factor > 0.5f ? t.gaits[1] : t.gaits[0];
  }
}

float leg_phase_offset(const AnimRig& rig, GaitFamily family, int leg, float mid_factor, float fast_factor) {
  const RigLeg& info = rig.legs[leg];
  const bool far = info.side == Side::kFar;
  const int n = static_cast<int>(rig.girdles.size());
  auto time = [&](int index) { return footfall_time(family, index, n, info.girdle, far); };
  // A foot whose phase runs ahead by x lands x cycles earlier.
  return frac(-circular_lerp(circular_lerp(time(0), time(1), mid_factor), time(2), fast_factor));
}

void update_target_offsets(const AnimRig& rig, GaitFamily family, GaitState& gait) {
  // The offsets follow the gait blend; a change below 1e-4 of it moves them by less than
  // 1e-4 of a cycle, which the feet's own easing towards them swallows.
  if (std::fabs(gait.mid_factor - gait.offsets_mid) < 1e-4f && std::fabs(gait.fast_factor - gait.offsets_fast) < 1e-4f &&
      gait.offsets_family == family && gait.target_offset.size() == rig.legs.size()) {
    return;
  }
  gait.offsets_mid = gait.mid_factor;
  gait.offsets_fast = gait.fast_factor;
  gait.offsets_family = family;
  gait.target_offset.resize(rig.legs.size());
  for (size_t i = 0; i < rig.legs.size(); ++i) {
    gait.target_offset[i] = leg_phase_offset(rig, family, static_cast<int>(i), gait.mid_factor, gait.fast_factor);
  }
}

void reset_offsets(const AnimRig& rig, GaitFamily family, const FootSet& feet, GaitState& gait) {
  gait.foot_offset.assign(feet.feet.size(), 0.0f);
  gait.foot_phase_prev.assign(feet.feet.size(), 0.0f);
  for (size_t i = 0; i < rig.legs.size(); ++i) {
    gait.foot_offset[feet.foot_of_leg[i]] = leg_phase_offset(rig, family, static_cast<int>(i), gait.mid_factor, gait.fast_factor);
  }
}

void start_clock(GaitState& gait, const FootSet& feet, int lead) {
  gait.moving = true;
  gait.phase = frac(gait.duty - gait.foot_offset[feet.foot_of_leg[lead]]);
  for (size_t k = 0; k < gait.foot_offset.size(); ++k) gait.foot_phase_prev[k] = frac(gait.phase + gait.foot_offset[k]);
}

void tick_clock(const AnimRig& rig, GaitFamily family, const FootSet& feet, float speed, bool blocked, float dt, float ism, GaitState& gait,
                std::vector<LegPhase>& leg_phase) {
  if (!(speed > 0.0f && !blocked)) {
    rest(gait, dt);
    return;
  }
  const bool starting = !gait.moving;
  if (starting) start_clock(gait, feet, 0);  // the lead leg lifts now; its first step is half a stride
  gait.phase = frac(gait.phase + gait.frequency * dt);
  update_target_offsets(rig, family, gait);
  leg_phase.resize(rig.legs.size());
  for (size_t i = 0; i < rig.legs.size(); ++i) {
    const int foot = feet.foot_of_leg[i];
    const bool stance = feet.feet[foot].state == LegState::kStance;
    leg_phase[i] = advance_leg_phase(gait, foot, stance, gait.target_offset[i], starting, ism, dt);
    end_leg_phase(gait, foot, leg_phase[i]);
  }
}

void rest(GaitState& gait, float dt) {
  gait.moving = false;
  gait.idle_time += dt;
}

void tick_crawl(const AnimRig& rig, float speed, bool blocked, float dt, GaitState& gait) {
  gait.crawl_phase = frac(gait.crawl_phase + speed * dt / std::max(rig.body_half_length, 0.05f));
  gait.gait = !blocked && speed > 0.0f ? Gait::kCrawl : Gait::kIdle;
  gait.idle_time += dt;
}


}  // namespace anim
}  // namespace ossa
