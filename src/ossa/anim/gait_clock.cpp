#include "ossa/anim/gait_clock.h"

#include <algorithm>
#include <cmath>

#include "ossa/anim/anim_math.h"

namespace ossa {

const char* gait_name(Gait gait) {
  switch (gait) {
    case Gait::kIdle: return "idle";
    case Gait::kWalk: return "walk";
    case Gait::kRun: return "run";
    case Gait::kTrot: return "trot";
    case Gait::kGallop: return "gallop";
    case Gait::kCrawl: return "crawl";
  }
  return "unknown";
}

namespace anim {

namespace {

// The gait blends ramp between these fractions of their Froude numbers.
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
// Froude number of the full run (full stick with run).
constexpr float kRunFroude = 2.5f;

}  // namespace

float walk_speed(const AnimRig& rig, const AnimatorParams& params) { return std::sqrt(0.5f * params.gravity * rig.hip_height); }
float run_speed(const AnimRig& rig, const AnimatorParams& params) { return std::sqrt(kRunFroude * params.gravity * rig.hip_height); }

GaitBands gait_bands(const AnimRig& rig, const AnimatorParams& params) {
  auto speed = [&](float froude) { return std::sqrt(std::max(froude, 0.0f) * params.gravity * rig.hip_height); };
  GaitBands b;
  if (rig.girdles.size() >= 2) {
    b.trot = speed(params.trot_froude);
    b.gallop = speed(params.gallop_froude);
  } else if (!rig.girdles.empty()) {
    b.run = speed(0.5f * (params.run_froude_start + params.run_froude_end));
  }
  b.full_run = run_speed(rig, params);
  return b;
}

void update_gait(const AnimRig& rig, const AnimatorParams& params, float speed, float keep_run, float keep_gait,
                 GaitState& gait) {
  gait.froude = speed * speed / (params.gravity * rig.hip_height);
  gait.run_factor = approach(gait.run_factor, smoothstep(params.run_froude_start, params.run_froude_end, gait.froude), keep_run);
  float trot = smoothstep(kTrotBandLow * params.trot_froude, kTrotBandHigh * params.trot_froude, gait.froude);
  float gallop = smoothstep(kGallopBandLow * params.gallop_froude, kGallopBandHigh * params.gallop_froude, gait.froude);
  if (params.gait_override != GaitOverride::kAuto) {
    trot = params.gait_override == GaitOverride::kWalk ? 0.0f : 1.0f;
    gallop = params.gait_override == GaitOverride::kGallop ? 1.0f : 0.0f;
  }
  gait.trot_factor = approach(gait.trot_factor, trot, keep_gait);
  gait.gallop_factor = approach(gait.gallop_factor, gallop, keep_gait);
  gait.duty = params.duty_walk + (params.duty_run - params.duty_walk) * gait.run_factor;

  // Stride: Alexander's relation, limited so that a stance foot half a stance ahead or
  // behind its girdle stays within reach.
  if (gait.froude != gait.stride_froude) {
    gait.stride_froude = gait.froude;
    gait.stride_pow = std::pow(std::max(gait.froude, 1e-4f), kStrideFroudeExponent);
  }
  const float stride = kStrideOfHip * rig.hip_height * gait.stride_pow * params.step_distance_multiplier;
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
  } else if (rig.girdles.size() == 1) {
    gait.gait = gait.run_factor > 0.5f ? Gait::kRun : Gait::kWalk;
  } else {
    gait.gait = gait.gallop_factor > 0.5f ? Gait::kGallop : gait.trot_factor > 0.5f ? Gait::kTrot : Gait::kWalk;
  }
}

float leg_phase_offset(const AnimRig& rig, int leg, float trot_factor, float gallop_factor) {
  const RigLeg& info = rig.legs[leg];
  const bool far = info.side == Side::kFar;
  const int n = static_cast<int>(rig.girdles.size());
  if (n == 1) return far ? 0.5f : 0.0f;
  if (n == 2) {
    const bool front = info.girdle == 0;
    // Footfall patterns as phase offsets (hind near = 0): lateral-sequence walk, trot
    // (diagonal pairs), transverse gallop.
    const float walk = front ? (far ? 0.75f : 0.25f) : (far ? 0.5f : 0.0f);
    const float trot = front ? (far ? 0.0f : 0.5f) : (far ? 0.5f : 0.0f);
    const float gallop = front ? (far ? 0.62f : 0.5f) : (far ? 0.12f : 0.0f);
    return circular_lerp(circular_lerp(walk, trot, trot_factor), gallop, gallop_factor);
  }
  // More pairs: a metachronal (tripod-like) wave, alternating down the body.
  const float near = static_cast<float>(info.girdle % 2) * 0.5f;
  return far ? frac(near + 0.5f) : near;
}

void update_target_offsets(const AnimRig& rig, GaitState& gait) {
  // The offsets follow the gait blend; a change below 1e-4 of it moves them by less than
  // 1e-4 of a cycle, which the feet's own easing towards them swallows.
  if (std::fabs(gait.trot_factor - gait.offsets_trot) < 1e-4f && std::fabs(gait.gallop_factor - gait.offsets_gallop) < 1e-4f &&
      gait.target_offset.size() == rig.legs.size()) {
    return;
  }
  gait.offsets_trot = gait.trot_factor;
  gait.offsets_gallop = gait.gallop_factor;
  gait.target_offset.resize(rig.legs.size());
  for (size_t i = 0; i < rig.legs.size(); ++i) {
    gait.target_offset[i] = leg_phase_offset(rig, static_cast<int>(i), gait.trot_factor, gait.gallop_factor);
  }
}

void reset_offsets(const AnimRig& rig, const FootSet& feet, GaitState& gait) {
  gait.foot_offset.assign(feet.feet.size(), 0.0f);
  gait.foot_phase_prev.assign(feet.feet.size(), 0.0f);
  for (size_t i = 0; i < rig.legs.size(); ++i) {
    gait.foot_offset[feet.foot_of_leg[i]] = leg_phase_offset(rig, static_cast<int>(i), gait.trot_factor, gait.gallop_factor);
  }
}

void start_clock(GaitState& gait, const FootSet& feet, int lead) {
  gait.moving = true;
  gait.phase = frac(gait.duty - gait.foot_offset[feet.foot_of_leg[lead]]);
  for (size_t k = 0; k < gait.foot_offset.size(); ++k) gait.foot_phase_prev[k] = frac(gait.phase + gait.foot_offset[k]);
}

void tick_clock(const AnimRig& rig, const FootSet& feet, float speed, bool blocked, float dt, float ism, GaitState& gait,
                std::vector<LegPhase>& leg_phase) {
  if (!(speed > 0.0f && !blocked)) {
    rest(gait, dt);
    return;
  }
  const bool starting = !gait.moving;
  if (starting) start_clock(gait, feet, 0);  // the lead leg lifts now; its first step is half a stride
  gait.phase = frac(gait.phase + gait.frequency * dt);
  update_target_offsets(rig, gait);
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
