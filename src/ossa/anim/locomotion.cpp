#include "ossa/anim/locomotion.h"

#include <algorithm>
#include <cmath>

#include "ossa/anim/anim_math.h"
#include "ossa/anim/animator_params.h"
#include "ossa/anim/body_motion.h"
#include "ossa/anim/foothold.h"
#include "ossa/anim/leg_ik.h"
#include "ossa/anim/swing.h"

namespace ossa {

const char* locomotion_name(Locomotion mode) {
  switch (mode) {
    case Locomotion::kGrounded: return "grounded";
    case Locomotion::kCrouch: return "crouch";
    case Locomotion::kAirborne: return "airborne";
    case Locomotion::kLanding: return "landing";
  }
  return "unknown";
}

namespace anim {

namespace {

// A hanging foot under its girdle, in contact reaches: tucked (extension 0) and reaching for
// the ground (1), how far below the joint and how far ahead of it (front legs) or behind
// (hind legs; a single girdle's legs hang a little ahead).
constexpr float kTuckDown = 0.55f, kReachDown = 0.9f;
constexpr float kTuckAheadFront = 0.3f, kReachAheadFront = 0.15f;
constexpr float kTuckBehindHind = 0.25f, kReachBehindHind = 0.05f;
constexpr float kTuckAheadSingle = 0.2f, kReachAheadSingle = 0.05f;
// A foot's offset from its air target eases away at this rate (1/s); a foot reaching down to
// ground below it (stepping down a drop within reach) comes down at that rate and at least
// this many rest heights of its girdle a second.
constexpr float kAirEaseRate = 12.0f;
constexpr float kReachDownOfRestPerSecond = 1.0f;
// The legs reach for the ground once it is within this many hip heights below where the feet
// would stand, plus what the fall covers in kReachLeadSeconds.
constexpr float kReachStartOfHip = 0.6f, kReachFullOfHip = 0.1f;
constexpr float kReachLeadSeconds = 0.12f;
// Landing: the legs give at most this many hip heights (twice it in a hard landing), and the
// descent takes at most this long.
constexpr float kMaxCompressionOfHip = 0.35f;
constexpr float kMaxDescentSeconds = 0.35f;
// A jump's feet leave the ground once their legs are this many times their standing length.
constexpr float kPushOffOfStanding = 1.15f;
// A legless body falls off a drop deeper than this share of its length.
constexpr float kLeglessFallOfLength = 0.25f;
// The crouch lasts at least this long, seconds.
constexpr float kMinCrouchSeconds = 0.05f;

void plant(const AnimContext& ctx, FootState& f, glm::vec2 p) {
  f.state = LegState::kStance;
  f.air = false;
  f.pos_ws = f.from_ws = f.to_ws = p;
  f.progress = 0.0f;
  f.easing = false;
  f.hover = 0.0f;
  f.hang_beyond = NAN;
  note_ledge(ctx, f, f.floor < 1e29f ? f.floor + kFloorBelowLedge : NAN);
  f.floor = 1e30f;
  update_stance_clearance(ctx, f);
}

// How far the legs reach for the ground, in [0, 1]: tucked while rising or high above it.
float reach_extension(const AnimContext& ctx, const BodyFrame& body, const LocomotionState& loco) {
  if (loco.vy >= 0.0f) return 0.0f;
  const AnimRig& rig = ctx.rig;
  const float feet_y = body.root_y_ws - rig.root_rest_y * ctx.params.stance_height;
  auto ground = ground_below(ctx.level, rig.body_lo_ws(body.x_ws, body.facing), rig.body_hi_ws(body.x_ws, body.facing), feet_y, 100.0f);
  if (!ground) return 0.0f;
  const float gap = feet_y - ground->height_ws;
  const float lead = -loco.vy * kReachLeadSeconds;
  return 1.0f - smoothstep(kReachFullOfHip * rig.hip_height, kReachStartOfHip * rig.hip_height + lead, gap);
}

// A girdle keeps this fraction of its rest height above the ground under it, looked for
// kBodyGroundHalfOfRest of it either side (as body placement's clamp 5).
constexpr float kBodyKeepOutOfRest = 0.12f, kBodyGroundHalfOfRest = 0.1f;

// Turns the body about its front girdle so that girdle `g` rises by dy.
void tip_about_front(const AnimRig& rig, int g, float dy, BodyFrame& body) {
  const glm::vec2 front = rig.girdles.front().joint_ms, joint = rig.girdles[g].joint_ms;
  const float len = glm::length(joint - front);
  if (len < 1e-4f) {
    body.root_y_ws += dy;
    return;
  }
  const glm::vec2 before = body.girdle_ws(rig, 0);
  // Behind the front girdle (facing space), rising turns the nose down.
  body.pitch -= std::asin(std::clamp(dy / len, -1.0f, 1.0f));
  body.root_y_ws += before.y - body.girdle_ws(rig, 0).y;
}

// The body meeting the ground before any foot (the legless, short legs on a slope) stands on
// it there (true). A girdle still over the ledge a fall left (ground at `floor` or above) does
// not land on it: the body tips over its edge instead, turning about the front girdle.
bool body_meets_ground(const AnimContext& ctx, float floor, BodyFrame& body) {
  const AnimRig& rig = ctx.rig;
  if (rig.girdles.empty()) {
    auto hit = ground_below(ctx.level, rig.body_lo_ws(body.x_ws, body.facing), rig.body_hi_ws(body.x_ws, body.facing),
                            std::min(body.root_y_ws + 0.5f * rig.hip_height, floor), 100.0f);
    if (!hit || hit->height_ws + rig.root_rest_y <= body.root_y_ws) return false;
    body.root_y_ws = hit->height_ws + rig.root_rest_y;
    return true;
  }
  bool landed = false;
  for (int g = static_cast<int>(rig.girdles.size()) - 1; g >= 0; --g) {
    const glm::vec2 joint = body.girdle_ws(rig, g);
    const float rest = rig.girdles[g].rest_height;
    const float half = kBodyGroundHalfOfRest * rest;
    auto hit = ground_below(ctx.level, joint.x - half, joint.x + half, joint.y + 0.5f * rest, 100.0f);
    if (!hit) continue;
    const float need = hit->height_ws + kBodyKeepOutOfRest * rest - joint.y;
    if (need <= 0.0f) continue;
    if (hit->height_ws >= floor && g > 0) {
      tip_about_front(rig, g, need, body);
    } else {
      body.root_y_ws += need;
      landed = true;
    }
  }
  return landed;
}

}  // namespace

float jump_speed(const AnimRig& rig, const AnimatorParams& params) {
  return std::sqrt(2.0f * params.gravity * std::max(params.jump_height, 0.0f) * rig.hip_height);
}

void begin_crouch(const AnimRig& rig, const AnimatorParams& params, LocomotionState& loco) {
  loco.mode = Locomotion::kCrouch;
  loco.time = 0.0f;
  loco.crouch = 0.0f;
  loco.crouch_seconds = std::max(params.jump_crouch_time * std::sqrt(rig.hip_height / params.gravity), kMinCrouchSeconds);
}

bool advance_crouch(const AnimRig& rig, const AnimatorParams& params, float dt, LocomotionState& loco) {
  loco.time += dt;
  const float s = std::min(loco.time / loco.crouch_seconds, 1.0f);
  loco.crouch = params.jump_crouch * rig.hip_height * smoothstep(0.0f, 1.0f, s);
  return s >= 1.0f;
}

glm::vec2 air_target(const AnimContext& ctx, const BodyFrame& body, int leg, float extension) {
  const AnimRig& rig = ctx.rig;
  const RigLeg& info = rig.legs[leg];
  const int n = static_cast<int>(rig.girdles.size());
  const float e = std::clamp(extension, 0.0f, 1.0f);
  float ahead = kTuckAheadSingle + e * (kReachAheadSingle - kTuckAheadSingle);
  if (n > 1 && info.girdle == 0) ahead = kTuckAheadFront + e * (kReachAheadFront - kTuckAheadFront);
  if (n > 1 && info.girdle == n - 1) ahead = -(kTuckBehindHind + e * (kReachBehindHind - kTuckBehindHind));
  const float down = kTuckDown + e * (kReachDown - kTuckDown);
  const glm::vec2 joint = body.girdle_ws(rig, info.girdle);
  const float r = info.contact_reach;
  return {joint.x + static_cast<float>(body.facing) * ahead * r, joint.y - down * r};
}

void hang(const AnimContext& ctx, const BodyFrame& body, int leg, float extension, FootState& f) {
  const glm::vec2 target = air_target(ctx, body, leg, extension);
  f.state = LegState::kSwing;
  f.air = true;
  f.easing = false;
  f.hover = 0.0f;
  f.progress = 0.0f;
  f.air_offset = f.pos_ws - target;
  f.from_ws = f.to_ws = f.pos_ws;
  f.swing_clear = Clearance{};  // knows nothing: the leg IK tests the hanging leg against the level
}

int update_air_feet(const AnimContext& ctx, const BodyFrame& body, float extension, float dt, bool reach_ground, FootSet& feet,
                    bool may_land) {
  if (std::none_of(feet.feet.begin(), feet.feet.end(), [](const FootState& f) { return f.air; })) return 0;
  const float keep = std::exp(-kAirEaseRate * dt);
  int planted = 0;
  for (size_t i = 0; i < ctx.rig.legs.size(); ++i) {
    const int leg = static_cast<int>(i);
    FootState& f = feet.of_leg(leg);
    if (!f.air) continue;
    glm::vec2 target = air_target(ctx, body, leg, extension);
    // A foot stepping off a drop reaches past its edge.
    if (!std::isnan(f.hang_beyond) && (target.x - f.hang_beyond) * static_cast<float>(body.facing) < 0.0f) {
      target.x = f.hang_beyond;
    }
    f.air_offset *= keep;
    glm::vec2 next = target + f.air_offset;
    const RigLeg& info = ctx.rig.legs[i];
    const FootSpan span = foot_span_ws(info, body.facing);
    if (reach_ground) {
      // On the ground (stepping off, landing) a hanging foot reaches down to ground its leg
      // reaches below it, so a drop within the legs' reach is stepped down, not fallen.
      const glm::vec2 j = body.girdle_ws(ctx.rig, info.girdle);
      const float r = kFootReach * info.contact_reach, dx = next.x - j.x;
      if (std::fabs(dx) < r) {
        const float lowest = j.y - std::sqrt(r * r - dx * dx);
        if (auto hit = ground_below(ctx.level, next.x + span.lo, next.x + span.hi, std::min(f.pos_ws.y, f.floor), f.pos_ws.y - lowest);
            hit && hit->height_ws < next.y) {
          // Down to it at the rate the air offset eases (no jump), planted on arrival.
          const float ground = hit->height_ws - 1e-3f;
          next.y = std::max(ground, f.pos_ws.y + (ground - f.pos_ws.y) * (1.0f - keep) - kReachDownOfRestPerSecond *
                                                     ctx.rig.girdles[info.girdle].rest_height * dt);
        }
      }
    }
    // Touch-down: the top of a box under the whole foot, met on the way down, plants it; the
    // ledge a fall left (f.floor and above) only carries it along — unless the foot, stepping
    // off, is a foot's length past the ledge's edge: ground there is the far side of a gap.
    if (next.y < f.pos_ws.y + 1e-3f) {
      const float from = f.pos_ws.y + 1e-3f;
      const bool across =
          !std::isnan(f.hang_beyond) && (next.x - f.hang_beyond) * static_cast<float>(body.facing) > info.foot_length;
      if (auto hit = ground_below(ctx.level, next.x + span.lo, next.x + span.hi, from, from - next.y + 1e-3f);
          hit && hit->height_ws >= next.y - 1e-3f) {
        if ((hit->height_ws < f.floor || across) && may_land) {
          plant(ctx, f, {next.x, hit->height_ws});
          ++planted;
          continue;
        }
        next.y = hit->height_ws;
      }
    }
    // Not into a wall: the line from the girdle joint to the foot stops short of the first box
    // (a leg reaching ahead into the far side of a gap is drawn back).
    const glm::vec2 joint = body.girdle_ws(ctx.rig, info.girdle);
    if (auto hit = ctx.level.raycast(joint, next); hit && hit->t < 1.0f) next = joint + (next - joint) * std::max(hit->t - 0.02f, 0.0f);
    f.pos_ws = f.from_ws = f.to_ws = next;
  }
  return planted;
}

void take_off(const AnimContext& ctx, const BodyFrame& body, glm::vec2 velocity, bool jump, FootSet& feet, LocomotionState& loco) {
  const AnimRig& rig = ctx.rig;
  loco.mode = Locomotion::kAirborne;
  loco.time = 0.0f;
  loco.crouch = 0.0f;
  loco.origin_y = loco.start_y = loco.top_y = body.root_y_ws;
  loco.vy0 = loco.vy = velocity.y;
  loco.vx = velocity.x;
  loco.jumped = jump;
  ++(jump ? loco.stats.jumps : loco.stats.falls);
  // A fall lands nowhere as high as the ground it left (the highest ledge a foot stepped off).
  float floor = 1e30f;
  if (!jump && rig.legs.empty()) {
    floor = body.root_y_ws - rig.root_rest_y - kFloorBelowLedge;  // the legless: the ground it crawled off
  } else if (!jump) {
    for (const FootState& f : feet.feet) {
      const float left = f.floor < 1e29f ? f.floor : f.state == LegState::kStance && !f.air ? f.pos_ws.y - kFloorBelowLedge : -1e30f;
      floor = floor < 1e29f ? std::max(floor, left) : left;
    }
    if (floor < -1e29f) floor = 1e30f;
  }
  loco.floor = floor;
  const int n = static_cast<int>(rig.girdles.size());
  for (size_t i = 0; i < rig.legs.size(); ++i) {
    FootState& f = feet.of_leg(static_cast<int>(i));
    f.floor = floor;
    if (f.air) continue;
    // A jump's feet on the ground push off until their legs are stretched (airborne_tick); a
    // quadruped's front feet leave first, so the hind legs push last.
    const bool front = n > 1 && rig.legs[i].girdle == 0;
    if (jump && f.state == LegState::kStance && !front) continue;
    hang(ctx, body, static_cast<int>(i), 0.0f, f);
  }
}

bool legless_over_drop(const AnimContext& ctx, const BodyFrame& body) {
  // Once the whole body has left a ledge, a drop deeper than a share of the body's length is
  // fallen (a smaller one, or a tile slope, the body follows down).
  const AnimRig& rig = ctx.rig;
  const float ground = body.root_y_ws - rig.root_rest_y;
  const float deepest = kLeglessFallOfLength * (rig.body_front - rig.body_back);
  // (From above the root: a landing's compression may hold the root below its rest height.)
  const float from = std::max(body.root_y_ws, ground) + 0.5f * rig.hip_height;
  return !ground_below(ctx.level, rig.body_lo_ws(body.x_ws, body.facing), rig.body_hi_ws(body.x_ws, body.facing), from,
                       from - (ground - deepest));
}

bool unsupported(const FootSet& feet) {
  bool any = false;
  for (const FootState& f : feet.feet) {
    if (!f.air) return false;
    any = true;
  }
  return any;
}

bool airborne_tick(const AnimContext& ctx, float dt, float keep_level, const std::vector<Mat2x3>& model_fs,
                   std::vector<Box>& boxes, BodyFrame& body, FootSet& feet, LocomotionState& loco) {
  const AnimRig& rig = ctx.rig;
  const float g = ctx.params.gravity;
  loco.time += dt;
  loco.stats.airborne_s += dt;
  // Horizontally the wall sweep: a jump into a wall stops at its face.
  if (loco.vx != 0.0f) {
    const BodyMotionResult swept = sweep_body(ctx, body, model_fs, loco.vx * dt, boxes, true);
    if (swept.hit_wall) loco.vx = 0.0f;
    body.x_ws += swept.dx;
  }
  // Vertically the ballistic path, in closed form from its origin (no integration error: the
  // apex is the ballistic one); a ceiling stops the rise.
  float y = loco.origin_y + loco.vy0 * loco.time - 0.5f * g * loco.time * loco.time;
  loco.vy = loco.vy0 - g * loco.time;
  if (y > body.root_y_ws) {
    body_boxes(rig, body, model_fs, false, &boxes);
    if (!boxes.empty()) {
      const Box top{{boxes[0].min_ws.x, boxes[0].max_ws.y - 0.01f}, boxes[0].max_ws};
      if (auto hit = ctx.level.sweep_box(top, {0.0f, y - body.root_y_ws}); hit && hit->t < 1.0f) {
        y = body.root_y_ws + std::max(hit->t * (y - body.root_y_ws) - 1e-4f, 0.0f);
        loco.origin_y = y;
        loco.vy0 = loco.vy = 0.0f;
        loco.time = 0.0f;
      }
    }
  }
  body.root_y_ws = y;
  loco.top_y = std::max(loco.top_y, y);
  body.pitch = approach(body.pitch, 0.0f, keep_level);
  body.lean = approach(body.lean, 0.0f, keep_level);
  // Feet still on the ground push off until their legs are stretched past their standing
  // length (a bird's crouched legs reach much further than they stand: they leave the ground
  // long before they are straight), or the reach, and none stays once the body comes down.
  for (size_t i = 0; i < rig.legs.size(); ++i) {
    const int leg = static_cast<int>(i);
    FootState& f = feet.of_leg(leg);
    if (f.state != LegState::kStance) continue;
    const glm::vec2 joint = body.to_fs(body.girdle_ws(rig, rig.legs[i].girdle));
    float r;
    const glm::vec2 anchor = leg_anchor(ctx, body, leg, body.to_fs(f.pos_ws), joint, f.stance_clear, &r);
    const float standing = kPushOffOfStanding * rig.girdles[rig.legs[i].girdle].rest_height * ctx.params.stance_height;
    if (glm::length(anchor - joint) > std::min(r, standing) || loco.vy <= 0.0f) hang(ctx, body, leg, 0.0f, f);
  }
  bool any_stance = false;
  for (const FootState& f : feet.feet) any_stance = any_stance || f.state == LegState::kStance;
  // (Rising, a foot that pushed off is carried along the ground, not planted again.)
  const int planted = update_air_feet(ctx, body, reach_extension(ctx, body, loco), dt, false, feet, loco.vy < 0.0f);
  if (planted > 0) return true;
  if (any_stance || loco.vy >= 0.0f) return false;
  return body_meets_ground(ctx, feet.feet.empty() ? loco.floor : feet.feet[0].floor, body);
}

void begin_landing(const AnimContext& ctx, const BodyFrame& body, float standing_root, LocomotionState& loco) {
  const AnimRig& rig = ctx.rig;
  const AnimatorParams& params = ctx.params;
  const float fall = loco.top_y - body.root_y_ws;
  loco.stats.max_fall_m = std::max(loco.stats.max_fall_m, fall);
  if (loco.jumped) loco.stats.max_jump_height_m = std::max(loco.stats.max_jump_height_m, loco.top_y - loco.start_y);
  const bool hard = fall > params.hard_landing * rig.hip_height;
  loco.stats.hard_landings += hard ? 1 : 0;
  // The legs give with the speed of the fall: landing_compression hip heights after a fall of
  // one hip height, growing with the speed, at most kMaxCompressionOfHip (twice both, hard).
  const float v = std::min(loco.vy, 0.0f);
  const float v_ref = std::sqrt(2.0f * params.gravity * rig.hip_height);
  const float most = (hard ? 2.0f : 1.0f) * kMaxCompressionOfHip * rig.hip_height;
  const float depth = std::min((hard ? 2.0f : 1.0f) * params.landing_compression * rig.hip_height * (-v / v_ref), most);
  loco.mode = Locomotion::kLanding;
  loco.time = 0.0f;
  loco.land_y = body.root_y_ws;
  loco.land_v = v;
  loco.land_low = std::min(standing_root, body.root_y_ws) - depth;
  // Slowing evenly from v to rest over the distance takes 2·distance/|v| (no longer than
  // kMaxDescentSeconds): a cubic with those end slopes never dips below land_low.
  const float distance = loco.land_y - loco.land_low;
  loco.land_seconds = -v > 1e-3f ? std::min(2.0f * distance / -v, kMaxDescentSeconds) : kMaxDescentSeconds;
}

float landing_root(const LocomotionState& loco) {
  if (loco.mode != Locomotion::kLanding || loco.time >= loco.land_seconds) return NAN;
  const float T = loco.land_seconds, s = loco.time / T;
  // Hermite from (land_y, slope land_v·T) to (land_low, slope 0).
  const float h00 = (2.0f * s - 3.0f) * s * s + 1.0f, h10 = ((s - 2.0f) * s + 1.0f) * s, h01 = (3.0f - 2.0f * s) * s * s;
  return h00 * loco.land_y + h10 * loco.land_v * T + h01 * loco.land_low;
}

}  // namespace anim
}  // namespace ossa
