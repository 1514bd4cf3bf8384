#include "ossa/anim/locomotion.h"

#include <algorithm>
#include <cmath>

#include "ossa/anim/anim_math.h"
#include "ossa/anim/animator_params.h"
#include "ossa/anim/body_motion.h"
#include "ossa/anim/foothold.h"
#include "ossa/anim/gait_clock.h"
#include "ossa/anim/leg_geometry.h"

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

// The legs reach for the ground once it is within this many hip heights below where the feet
// would stand, plus what the fall covers in kReachLeadSeconds.
constexpr float kReachStartOfHip = 0.6f, kReachFullOfHip = 0.1f;
constexpr float kReachLeadSeconds = 0.12f;
// Landing: the legs give at most this many hip heights (twice it in a hard landing), and the
// descent takes at most this long.
constexpr float kMaxCompressionOfHip = 0.35f;
constexpr float kMaxDescentSeconds = 0.35f;
// A legless body falls off a drop deeper than this share of its length.
constexpr float kLeglessFallOfLength = 0.25f;
// The crouch lasts at least this long, seconds.
constexpr float kMinCrouchSeconds = 0.05f;

}  // namespace

float reach_extension(const AnimContext& ctx, const BodyFrame& body, const LocomotionState& loco) {
  if (loco.vy >= 0.0f) return 0.0f;
  const AnimRig& rig = ctx.rig;
  const float feet_y = body.root_y_ws - rig.root_rest_y * ctx.params.stance_height;
  auto ground = ground_below(ctx.level, rig.body_lo_ws(body.x_ws, body.facing), rig.body_hi_ws(body.x_ws, body.facing), feet_y, ctx.rig.scale.search_depth);
  if (!ground) return 0.0f;
  const float gap = feet_y - ground->height_ws;
  const float lead = -loco.vy * kReachLeadSeconds;
  return 1.0f - smoothstep(kReachFullOfHip * rig.hip_height, kReachStartOfHip * rig.hip_height + lead, gap);
}


float jump_rise(const AnimRig& rig, const AnimatorParams& params) {
  return std::max(params.jump_height, 0.0f) * std::max(rig.hip_height, kLeastJumpRiseM);
}

float jump_speed(const AnimRig& rig, const AnimatorParams& params) { return std::sqrt(2.0f * params.gravity * jump_rise(rig, params)); }

glm::vec2 jump_velocity(const AnimRig& rig, const AnimatorParams& params, float speed, float asked, bool blocked) {
  const float up = jump_speed(rig, params), forwards = std::max(speed, asked);
  const float full_run = run_speed(rig, params);
  if (blocked || !(full_run > 0.0f)) return {forwards, up};
  const float leap = up * std::sin(kLeapLeanMost * std::min(asked / full_run, 1.0f));
  if (leap <= forwards) return {forwards, up};
  return {leap, std::sqrt(std::max(up * up - leap * leap + forwards * forwards, 0.0f))};
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

void take_off(const AnimContext& ctx, const BodyFrame& body, glm::vec2 velocity, bool jump, const FootSet& feet,
              LocomotionState& loco) {
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
    floor = body.root_y_ws - rig.root_rest_y - rig.scale.ledge_gap;  // the legless: the ground it crawled off
  } else if (!jump) {
    for (const FootState& f : feet.feet) {
      const float left = f.floor < 1e29f ? f.floor : f.state == LegState::kStance && !f.air ? f.pos_ws.y - rig.scale.ledge_gap : -1e30f;
      floor = floor < 1e29f ? std::max(floor, left) : left;
    }
    if (floor < -1e29f) floor = 1e30f;
  }
  loco.floor = floor;
}

void begin_tick(const AnimRig& rig, const AnimatorParams& params, bool jump, float dt, LocomotionState& loco) {
  if (loco.mode == Locomotion::kLanding) loco.time += dt;
  if (jump && loco.mode == Locomotion::kGrounded && !rig.legs.empty()) begin_crouch(rig, params, loco);
}

bool tick_crouch(const AnimRig& rig, const AnimatorParams& params, float dt, LocomotionState& loco) {
  return loco.mode == Locomotion::kCrouch && advance_crouch(rig, params, dt, loco);
}

ModeChange mode_change(const AnimContext& ctx, const BodyFrame& body, const FootSet& feet, bool was_landing, bool crouch_done,
                       const LocomotionState& loco, float body_lift) {
  if (crouch_done) return ModeChange::kJump;
  if (!was_landing && (ctx.rig.legs.empty() ? legless_over_drop(ctx, body, body_lift) : unsupported(feet))) return ModeChange::kFall;
  if (was_landing && std::isnan(landing_root(loco))) return ModeChange::kLanded;
  return ModeChange::kNone;
}

bool below_kill_height(const AnimRig& rig, const BodyFrame& body, const Level& level) {
  // (The level's default kill margin scales with the creature: Level::kill_y.)
  return body.root_y_ws - rig.root_rest_y < level.kill_y(rig.hip_height);
}

bool legless_over_drop(const AnimContext& ctx, const BodyFrame& body, float body_lift) {
  // Once the whole body has left a ledge, a drop deeper than a share of the body's length is
  // fallen (a smaller one, or a tile slope, the body follows down).
  const AnimRig& rig = ctx.rig;
  const float ground = body.root_y_ws - rig.root_rest_y - std::max(body_lift, 0.0f);
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

bool fly_along(const AnimContext& ctx, float dt, const BodyFrame& body, const std::vector<Mat2x3>& model_fs,
               std::vector<Box>& boxes, LocomotionState& loco, float* dx) {
  loco.time += dt;
  loco.stats.airborne_s += dt;
  if (loco.vx == 0.0f) return false;
  // Horizontally the wall sweep: a jump into a wall stops at its face. Still rising, it only
  // waits there (a jump from against a step goes on over it once it has risen above it).
  const BodyMotionResult swept = sweep_body(ctx, body, model_fs, loco.vx * dt, boxes, true);
  if (swept.hit_wall && loco.vy <= 0.0f) loco.vx = 0.0f;
  *dx = swept.dx;
  return true;
}

float path_height(const AnimContext& ctx, const BodyFrame& body, const std::vector<Mat2x3>& model_fs, std::vector<Box>& boxes,
                  LocomotionState& loco) {
  const float g = ctx.params.gravity;
  // Vertically the ballistic path, in closed form from its origin (no integration error: the
  // apex is the ballistic one); a ceiling stops the rise.
  float y = loco.origin_y + loco.vy0 * loco.time - 0.5f * g * loco.time * loco.time;
  loco.vy = loco.vy0 - g * loco.time;
  if (y > body.root_y_ws) {
    body_boxes(ctx.rig, body, model_fs, false, &boxes);
    if (!boxes.empty()) {
      // A ceiling is a box above the body's top (the top centimetre of its box swept up); a
      // box beside the body or around part of it (the step a creature blocked at a stair
      // jumps from, its head already over the tread) is not: the rise goes on past it.
      const Box& b = boxes[0];
      const float rise = y - body.root_y_ws, strip = b.max_ws.y - 0.01f;
      ctx.hits.clear();
      ctx.level.overlapping(Box{{b.min_ws.x, strip}, {b.max_ws.x, b.max_ws.y + rise}}, ctx.hits);
      float room = rise;
      for (int h : ctx.hits) {
        const Box& c = ctx.level.box(h);
        if (c.min_ws.y >= strip) room = std::min(room, c.min_ws.y - b.max_ws.y);
      }
      if (room < rise) {
        y = body.root_y_ws + std::max(room - 1e-4f, 0.0f);
        loco.origin_y = y;
        loco.vy0 = loco.vy = 0.0f;
        loco.time = 0.0f;
      }
    }
  }
  loco.top_y = std::max(loco.top_y, y);
  return y;
}

float push_back_from_face(const AnimContext& ctx, const BodyFrame& body, const std::vector<Mat2x3>& model_fs, std::vector<Box>& boxes,
                          bool flesh, float most, const FootSet* stance, float legs_most) {
  const AnimRig& rig = ctx.rig;
  if (rig.body_slabs.empty()) return 0.0f;
  body_boxes(rig, body, model_fs, true, &boxes);
  // (The arms' reach boxes come last: the arms fold out of the way.)
  const size_t parts = boxes.size() - std::min(boxes.size(), rig.arms.size());
  // The trunk's bones (the rib cage below the spine's outline) as segments: a box around a
  // slanting rib reaches past the face by more than the rib does. The flesh too when asked,
  // the head's level with the skull (as the wall sweep takes it).
  thread_local std::vector<glm::vec2> segs;  // end points, two a segment
  segs.clear();
  for (size_t i = 0; i < rig.trunk_level_from; ++i) {
    segs.push_back(body.body_point_ws(rig, rig.trunk[i].a));
    segs.push_back(body.body_point_ws(rig, rig.trunk[i].b));
  }
  if (flesh && !rig.flesh.empty()) {
    const glm::vec2 skull_ms = rig.skull >= 0 ? bone_start(rig.model_rest[rig.skull]) : glm::vec2(0.0f);
    const glm::vec2 skull_fs = body.to_fs(body.body_point_ws(rig, skull_ms));
    for (size_t i = 0; i < rig.flesh.size(); ++i) {
      for (glm::vec2 p_ms : {rig.flesh[i].a, rig.flesh[i].b}) {
        segs.push_back(i < rig.flesh_level_from ? body.body_point_ws(rig, p_ms) : body.to_ws(skull_fs + (p_ms - skull_ms)));
      }
    }
  }
  // Is segment a-b inside collider c? Its x-range there in *x0, *x1.
  auto within = [](glm::vec2 a, glm::vec2 b, const Box& c, float* x0, float* x1) {
    return segment_x_within(a, b, c.min_ws.y, c.max_ws.y, x0, x1) && *x1 > c.min_ws.x && *x0 < c.max_ws.x;
  };
  float push = 0.0f;
  // Only a face ahead of the part (its near edge inside the part, its far side beyond), or
  // ahead of the root with the part come down past it (a point: an arm's shoulder, the eared
  // seal's, falling into drops.json's pit, came down 4.8 cm into the far wall).
  auto meet = [&](const Box& c, float lo, float hi) {
    const bool ahead = body.facing > 0 ? c.min_ws.x > std::min(lo, body.x_ws) : c.max_ws.x < std::max(hi, body.x_ws);
    if (ahead) push = std::max(push, body.facing > 0 ? hi - c.min_ws.x : c.max_ws.x - lo);
  };
  for (size_t k = 0; k < parts; ++k) {
    const Box& p = boxes[k];
    ctx.hits.clear();
    ctx.level.overlapping(p, ctx.hits);
    for (int h : ctx.hits) meet(ctx.level.box(h), p.min_ws.x, p.max_ws.x);
  }
  for (size_t k = 0; k < segs.size(); k += 2) {
    ctx.hits.clear();
    ctx.level.overlapping(Box{glm::min(segs[k], segs[k + 1]), glm::max(segs[k], segs[k + 1])}, ctx.hits);
    float x0, x1;
    for (int h : ctx.hits) {
      if (within(segs[k], segs[k + 1], ctx.level.box(h), &x0, &x1)) meet(ctx.level.box(h), x0, x1);
    }
  }
  // Back there, nothing of the body may be in a box (a gap narrower than the body: it stays):
  // the trunk's bones (and flesh, when asked), the hull's boxes too where `parts_too`.
  auto clear_at = [&](float back, bool parts_too) {
    const glm::vec2 shift(-body.facing * back, 0.0f);
    for (size_t k = 0; parts_too && k < parts; ++k) {
      if (ctx.level.first_overlap(Box{boxes[k].min_ws + shift, boxes[k].max_ws + shift})) return false;
    }
    for (size_t k = 0; k < segs.size(); k += 2) {
      const glm::vec2 a = segs[k] + shift, b = segs[k + 1] + shift;
      ctx.hits.clear();
      ctx.level.overlapping(Box{glm::min(a, b), glm::max(a, b)}, ctx.hits);
      float x0, x1;
      for (int h : ctx.hits) {
        if (within(a, b, ctx.level.box(h), &x0, &x1)) return false;
      }
    }
    return true;
  };
  if (push > 0.0f) push += 1e-3f;
  if (push > most || (push > 0.0f && !clear_at(push, true))) push = 0.0f;
  // The stance legs' outline goes back with the legs' own test (the hull's boxes are a bound
  // that may lie over a tread the body stands below: a pigeon's neck over a riser's top).
  if (stance) {
    const float legs = stance_flesh_push(ctx, body, *stance, legs_most);
    if (legs > push && clear_at(legs, false)) push = legs;
  }
  return push;
}

bool body_may_land(const LocomotionState& loco, const FootSet& feet, float* floor) {
  bool any_stance = false;
  for (const FootState& f : feet.feet) any_stance = any_stance || f.state == LegState::kStance;
  if (any_stance || loco.vy >= 0.0f) return false;
  *floor = feet.feet.empty() ? loco.floor : feet.feet[0].floor;
  return true;
}

void begin_landing(const AnimContext& ctx, const BodyFrame& body, float standing_root, LocomotionState& loco) {
  const AnimRig& rig = ctx.rig;
  const AnimatorParams& params = ctx.params;
  const float fall = loco.top_y - body.root_y_ws;
  loco.stats.max_fall_m = std::max(loco.stats.max_fall_m, fall);
  if (loco.jumped) loco.stats.max_jump_height_m = std::max(loco.stats.max_jump_height_m, loco.top_y - loco.start_y);
  // A small creature lands as it jumps (jump_rise: its muscles' work grows with its mass, as
  // the fall's does): its own half-metre jump, 15 hip heights for the frog, is no hard landing.
  const bool hard = fall > params.hard_landing * std::max(rig.hip_height, kLeastJumpRiseM);
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

void finish_landing(LocomotionState& loco) { loco.mode = Locomotion::kGrounded; }

float landing_root(const LocomotionState& loco) {
  if (loco.mode != Locomotion::kLanding || loco.time >= loco.land_seconds) return NAN;
  const float T = loco.land_seconds, s = loco.time / T;
  // Hermite from (land_y, slope land_v·T) to (land_low, slope 0).
  const float h00 = (2.0f * s - 3.0f) * s * s + 1.0f, h10 = ((s - 2.0f) * s + 1.0f) * s, h01 = (3.0f - 2.0f * s) * s * s;
  return h00 * loco.land_y + h10 * loco.land_v * T + h01 * loco.land_low;
}

}  // namespace anim
}  // namespace ossa
