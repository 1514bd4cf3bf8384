#include "ossa/anim/pentapedal.h"

#include <algorithm>
#include <cmath>

#include "ossa/anim/anim_math.h"
#include "ossa/anim/level_probe.h"
#include "ossa/math/angle.h"
#include "ossa/math/two_bone_ik.h"

namespace ossa::anim {

namespace {

// The posture: the body pitches nose down until its shoulders stand this share of the arms'
// reach (shoulder to wrist) above the girdle's ground, turning no further than kMaxPitch; the
// rest the girdle goes down, by at most kMaxCrouchOfRest of its rest height.
constexpr float kReachUse = 0.85f;
constexpr float kMaxPitch = 0.8f;  // radians (body placement turns no steeper than 0.9)
constexpr float kMaxCrouchOfRest = 0.5f;
constexpr float kStanding = 0.97f;  // AnimatorParams::stance_height's default
// How fast the body goes down onto its forelimbs and rises again: a critically damped spring
// of this angular frequency (1/s), so the lean sets off and settles without a jolt (at most
// ω² of the whole lean a second squared: about half a g for a kangaroo).
constexpr float kEaseOmega = 4.0f;
// The hands stand this share of a cycle longer than the hind feet swing, at each end: for a
// moment all five supports are down.
constexpr float kOverlap = 0.05f;
// A swinging hand rises this share of the arm's reach; the tail lifts this share of the hip
// height while the hind feet stand.
constexpr float kHandLiftOfReach = 0.15f;
constexpr float kTailLiftOfHip = 0.08f;
constexpr float kHandForward = 0.8f;
// Hands and tail keep this far above the ground they touch (metres; the metrics count a
// millimetre).
constexpr float kTouch = 0.003f;
// The most the tail bends down along its length (radians).
constexpr float kMaxTailPress = 1.5f;
constexpr int kPressBisections = 12;
// Below this lean the walk is upright: nothing planted.
constexpr float kLeast = 1e-3f;

float lerp_angle(float from, float to, float t) { return from + t * wrap_angle(to - from); }

}  // namespace

void build_pentapedal(AnimRig& rig) {
  if (rig.girdles.size() != 1 || rig.arms.empty()) return;
  const RigGirdle& girdle = rig.girdles[0];
  const RigLimb& arm = rig.arms[0];
  const glm::vec2 s = bone_start(rig.model_rest[arm.bones[0]]) - girdle.joint_ms;
  const float reach = kReachUse * (rig.skeleton.length(arm.bones[0]) + rig.skeleton.length(arm.bones[1]));
  const float standing = kStanding * girdle.rest_height;
  // The shoulder's height over the girdle after a turn δ nose down: s.y·cos δ − s.x·sin δ
  // = |s|·cos(δ + α), α = atan2(s.x, s.y).
  const float length = glm::length(s);
  if (!(length > 0.0f)) return;
  const float alpha = std::atan2(s.x, s.y);
  const float pitch = std::clamp(std::acos(std::clamp((reach - standing) / length, -1.0f, 1.0f)) - alpha, 0.0f, kMaxPitch);
  const float over = length * std::cos(pitch + alpha);  // the shoulder over the girdle, turned
  rig.pentapedal_pitch = pitch;
  rig.pentapedal_crouch = std::clamp(standing + over - reach, 0.0f, kMaxCrouchOfRest * girdle.rest_height);
}

void ease_pentapedal(bool steady, float dt, GaitState& gait) {
  if (!gait.traits.pentapedal) {
    gait.pentapedal = gait.pentapedal_rate = 0.0f;
    return;
  }
  if (!gait.moving || !steady) {  // held where it is
    gait.pentapedal_rate = 0.0f;
    return;
  }
  const float target = 1.0f - gait.mid_factor;
  gait.pentapedal_rate += dt * (kEaseOmega * kEaseOmega * (target - gait.pentapedal) - 2.0f * kEaseOmega * gait.pentapedal_rate);
  gait.pentapedal = std::clamp(gait.pentapedal + dt * gait.pentapedal_rate, 0.0f, 1.0f);
}

// Where in its cycle the walk is: the hind feet stand for s < duty, the hands (and the tail)
// from duty − kOverlap to kOverlap past the cycle's end; `swing` is the hands' swing done.
struct Timing {
  float s = 0.0f, swing = 0.0f;
  bool hands_down = true;
};

Timing timing(const AnimRig& rig, const FootSet& feet, const GaitState& gait) {
  Timing t;
  t.s = frac(gait.phase + gait.foot_offset[feet.foot_of_leg[rig.girdles[0].legs.front()]]);
  t.hands_down = !gait.moving || t.s >= gait.duty - kOverlap || t.s < kOverlap;
  t.swing = std::clamp((t.s - kOverlap) / std::max(gait.duty - 2.0f * kOverlap, 1e-3f), 0.0f, 1.0f);
  return t;
}

float hand_margin(const AnimRig& rig, const GaitState& gait) {
  return rig.scale.arm_margin + gait.pentapedal * (kTouch - rig.scale.arm_margin);
}

void plant_hands(const AnimContext& ctx, const BodyFrame& body, const FootSet& feet, const GaitState& gait,
                 const std::vector<Mat2x3>& model, PentapedalState& state, Pose& pose) {
  const AnimRig& rig = ctx.rig;
  const float w = gait.pentapedal;
  state.hands.resize(rig.arms.size());
  if (!(w > kLeast) || rig.girdles.size() != 1) {
    for (PentapedalHand& hand : state.hands) hand = {};
    return;
  }
  const float duty = gait.duty;
  const auto [s, swing, hands_down] = timing(rig, feet, gait);
  // Half the hands' stance travel: planted that far ahead of the shoulder, they are under it
  // at mid-stance.
  const float lead = 0.5f * gait.stride * (1.0f - duty + 2.0f * kOverlap);
  const float done = frac(s - (duty - kOverlap));  // of the cycle since the hands came down

  for (size_t a = 0; a < rig.arms.size(); ++a) {
    const RigLimb& arm = rig.arms[a];
    PentapedalHand& hand = state.hands[a];
    const Mat2x3& girdle = model[arm.girdle_bone];
    const glm::vec2 shoulder = girdle.apply(pose.locals[arm.bones[0]].offset_ls);  // facing space
    const glm::vec2 shoulder_ws = body.to_ws(shoulder);
    const float upper = rig.skeleton.length(arm.bones[0]), lower = rig.skeleton.length(arm.bones[1]);
    const float reach = upper + lower;
    auto ground_at = [&](float x, float* y) {
      const float half = 0.5f * rig.scale.ground_span;
      auto hit = ground_below(ctx.level, x - half, x + half, shoulder_ws.y, 1.5f * reach);
      if (hit) *y = hit->height_ws + kTouch;
      return hit.has_value();
    };
    // Where the hands come down next: ahead of where the shoulder will be then.
    const float next_x = shoulder_ws.x + body.facing * (gait.stride * std::max(duty - kOverlap - s, 0.0f) + lead);
    glm::vec2 target_ws;
    if (hands_down) {
      if (!hand.planted) {
        // Where its swing brought it (on the first tick: under the shoulder as far into its
        // stance as the walk is).
        float y;
        const float x = hand.known ? hand.at.x : shoulder_ws.x + body.facing * (lead - gait.stride * done);
        if (!ground_at(x, &y)) continue;  // nothing to stand on: the arm keeps its swing
        hand.at = {x, y};
        hand.planted = hand.known = true;
      }
      target_ws = hand.at;
    } else {
      if (hand.planted || !hand.known) {
        hand.from = hand.known ? hand.at : glm::vec2(shoulder_ws.x, shoulder_ws.y - reach);
        hand.planted = false;
        hand.known = true;
      }
      float y = hand.from.y;
      ground_at(next_x, &y);
      // Forward in the first kHandForward of the swing: the hand comes straight down.
      const float t = smoothstep(0.0f, kHandForward, swing);
      target_ws = hand.from + t * (glm::vec2(next_x, y) - hand.from);
      hand.at = target_ws;
      target_ws.y += kHandLiftOfReach * reach * std::sin(kPi * swing);
    }
    // Two-bone IK to the wrist, the elbow to the side it bends at rest; the hand flat forward.
    const glm::vec2 rs = bone_start(rig.model_rest[arm.bones[0]]), re = bone_start(rig.model_rest[arm.bones[1]]),
                    rw = bone_start(rig.model_rest[arm.bones[2]]);
    const glm::vec2 sw = rw - rs, se = re - rs;
    const float bend = sw.x * se.y - sw.y * se.x >= 0.0f ? 1.0f : -1.0f;
    const TwoBoneIkResult ik = solve_two_bone_ik_directions(shoulder, upper, lower, body.to_fs(target_ws), bend);
    const float upper_abs = std::atan2(ik.upper_dir.y, ik.upper_dir.x);
    const float lower_abs = std::atan2(ik.lower_dir.y, ik.lower_dir.x);
    const float parent = std::atan2(girdle.m[1], girdle.m[0]);
    const float want[3] = {wrap_angle(upper_abs - parent), wrap_angle(lower_abs - upper_abs), wrap_angle(0.0f - lower_abs)};
    for (int k = 0; k < 3; ++k) {
      float& angle = pose.locals[arm.bones[k]].angle_ls;
      angle = lerp_angle(angle, want[k], w);
    }
  }

}

void press_tail(const AnimContext& ctx, const BodyFrame& body, const FootSet& feet, const GaitState& gait,
                const std::vector<Mat2x3>& model, Pose& pose) {
  // The tail's tip down to the highest ground under the tail while the hands stand, lifted a
  // little while the hind feet do: every tail bone turns by an equal share of the bend.
  const AnimRig& rig = ctx.rig;
  const float w = gait.pentapedal;
  if (!(w > kLeast) || rig.girdles.size() != 1 || rig.tail.empty() || rig.tail_base_bone < 0) return;
  const auto [s, swing, hands_down] = timing(rig, feet, gait);
  Mat2x3 base = model[rig.tail_base_bone] * rig.tail_between_rest;
  for (int b : rig.tail_between) base = base * local_matrix(pose.locals[b]);
  const size_t n = rig.tail.size();
  auto lowest = [&](float turn, float* x_lo, float* x_hi) {
    Mat2x3 m = base;
    float y = 1e30f;
    for (size_t k = 0; k < n; ++k) {
      BoneLocal local = pose.locals[rig.tail[k]];
      local.angle_ls += turn / static_cast<float>(n);
      m = m * local_matrix(local);
      const glm::vec2 p = body.to_ws(bone_start(m)), e = body.to_ws(bone_end(m, rig.skeleton.length(rig.tail[k])));
      y = std::min({y, p.y, e.y});
      if (x_lo) *x_lo = std::min({*x_lo, p.x, e.x}), *x_hi = std::max({*x_hi, p.x, e.x});
    }
    return y;
  };
  float x_lo = 1e30f, x_hi = -1e30f;
  const float now = lowest(0.0f, &x_lo, &x_hi);
  auto ground = ground_below(ctx.level, x_lo, x_hi, now + rig.tail_length, 2.0f * rig.tail_length);
  if (!ground) return;
  const float lift = hands_down ? 0.0f : kTailLiftOfHip * rig.hip_height * std::sin(kPi * swing);
  const float goal = ground->height_ws + kTouch + lift;
  if (now <= goal) return;
  // The bend that brings the lowest point down to the goal (a positive turn lowers a tail
  // that trails behind, facing space).
  float lo = 0.0f, hi = kMaxTailPress;
  if (lowest(hi, nullptr, nullptr) > goal) {
    lo = hi;
  } else {
    for (int i = 0; i < kPressBisections; ++i) {
      const float mid = 0.5f * (lo + hi);
      (lowest(mid, nullptr, nullptr) > goal ? lo : hi) = mid;
    }
  }
  for (int b : rig.tail) pose.locals[b].angle_ls += w * lo / static_cast<float>(n);
}

}  // namespace ossa::anim
