#include "ossa/anim/body_placement.h"

// [SECTION] targets: girdle heights, pitch
// [SECTION] place_body
// [SECTION] the body's other transitions
// (The clamps are in body_clamps.cpp.)

#include <algorithm>
#include <cmath>

#include "ossa/anim/anim_math.h"
#include "ossa/anim/animator_params.h"
#include "ossa/anim/body_placement_internal.h"
#include "ossa/anim/foothold.h"
#include "ossa/anim/leg_geometry.h"

namespace ossa::anim {

using namespace placement;

namespace {

// [SECTION] targets: girdle heights, pitch ----------------------------------------------------


// Each girdle's target height: the mean ground under its feet (a swinging foot counts where
// it is between lift-off and landing), raised halfway to a higher step under the girdle, plus
// its standing height and the bob; a foot hovering above a lower step brings it down.
void girdle_heights(Placement& p, std::vector<float>& height) {
  const AnimRig& rig = p.ctx.rig;
  const AnimatorParams& params = p.ctx.params;
  for (size_t g = 0; g < rig.girdles.size(); ++g) {
    const RigGirdle& girdle = rig.girdles[g];
    float sum = 0.0f;
    int count = 0;
    for (int leg : girdle.legs) {
      const FootState& f = p.feet.of_leg(leg);
      if (f.air) {
        // Hanging over a drop: the ground a leg's reach and a half below it, if any, draws the
        // girdle down to it and a little lower, so the foot reaches it (a drop the legs can
        // step down); else it holds nothing up. Nor does a foot tucked up at a turn: its girdle
        // goes back over the ledge it hung from (the dimetrodon, turned back at drops.json's
        // 1 m ledge, pitched its hips 0.5 m down into the drop and its ribs into the ledge's
        // corner before the tucked feet met the top).
        if (f.tucked) continue;
        const float r = rig.legs[leg].contact_reach;
        const float span = 0.5f * rig.scale.ground_span;
        if (auto below = ground_below(p.ctx.level, f.pos_ws.x - span, f.pos_ws.x + span, std::min(f.pos_ws.y, f.floor), kHangGroundOfReach * r)) {
          sum += below->height_ws - kHangDipOfRest * girdle.rest_height;
          ++count;
        }
        continue;
      }
      sum += f.state == LegState::kStance ? f.pos_ws.y : f.from_ws.y + std::clamp(f.progress, 0.0f, 1.0f) * (f.to_ws.y - f.from_ws.y);
      ++count;
    }
    if (count == 0) {  // every foot hangs: the girdle stays where it is
      height[g] = p.body.girdle_ws(rig, static_cast<int>(g)).y;
      continue;
    }
    float ground = sum / static_cast<float>(count);
    // On stairs the feet straddle steps; a girdle over a higher step rises with it, so the
    // knees stay clear of the step they pass over.
    const float gx = p.body.girdle_ws(rig, static_cast<int>(g)).x;
    const float half = kGirdleGroundHalfOfRest * girdle.rest_height;
    if (auto below = p.ctx.ground.may_rise_above(gx - half, gx + half, ground, ground + params.max_step_up * girdle.step_height)
                         ? ground_below(p.ctx.level, gx - half, gx + half, ground + params.max_step_up * girdle.step_height,
                                        params.max_step_up * girdle.step_height)
                         : std::nullopt) {
      ground = std::max(ground, 0.5f * (ground + below->height_ws));
    }
    const float bob = g < p.in.bob.size() ? p.in.bob[g] : 0.0f;
    const float standing = ground + girdle.rest_height * params.stance_height + bob + p.in.extra_bob - p.in.crouch;
    // A foot waiting above a lower step (see the swing) brings its girdle down to it, but not
    // so far that a leg on the ground folds up (its knee would reach into the ground).
    float floor = -1e30f, lowest = standing;
    for (int leg : girdle.legs) {
      const FootState& f = p.feet.of_leg(leg);
      if (f.state == LegState::kStance) floor = std::max(floor, f.pos_ws.y + kLowestGirdleOfRest * girdle.rest_height);
      if (!p.waiting[p.feet.foot_of_leg[leg]]) continue;
      const glm::vec2 foot = f.to_ws;
      const float r = kFootReach * rig.legs[leg].contact_reach;
      const float dx = std::min(std::fabs(foot.x - gx), 0.95f * r);
      lowest = std::min(lowest, foot.y + reach_across(r, dx));
    }
    height[g] = std::min(standing, std::max(lowest, floor));
  }
}

// The root height and pitch that put the girdles at their heights.
void body_target(Placement& p, const std::vector<float>& height, float* target_root, float* target_pitch) {
  const AnimRig& rig = p.ctx.rig;
  const glm::vec2 root_rest(0.0f, rig.root_rest_y);
  const float angle_extra = p.body.lean;
  if (rig.girdles.size() >= 2) {
    const glm::vec2 df = p.body.girdle_ms(rig, 0) - root_rest, db = p.body.girdle_ms(rig, static_cast<int>(rig.girdles.size()) - 1) - root_rest;
    const glm::vec2 d = df - db;  // the rest chord between the girdles
    if (!(d == p.state.chord)) {
      p.state.chord = d;
      p.state.chord_length = std::sqrt(d.x * d.x + d.y * d.y);
      p.state.chord_angle = fast_atan2(d.y, d.x);
    }
    const float len = p.state.chord_length;
    const float dy = height.front() - height.back();
    const float total = std::asin(std::clamp(dy / std::max(len, 1e-4f), -0.9f, 0.9f)) - p.state.chord_angle;
    *target_pitch = std::clamp(wrap_angle(total - angle_extra), -kMaxTargetPitch, kMaxTargetPitch);
    const float a = *target_pitch + angle_extra;
    const float c = std::cos(a), s = std::sin(a);
    const float df_y = s * df.x + c * df.y, db_y = s * db.x + c * db.y;  // rotate(·, a).y
    *target_root = 0.5f * (height.front() - df_y + height.back() - db_y);
    return;
  }
  // A shoulder far ahead of the only girdle (a long-bodied bird) would run into the steps of
  // a steep flight before the legs climb them: the body pitches up so the shoulder keeps its
  // height above the ground ahead of it (a quarter second ahead).
  const glm::vec2 shoulder = rig.front_shoulder;
  if (shoulder.x > 0.0f) {
    const float ground = height.front() - rig.girdles.front().rest_height * p.ctx.params.stance_height;
    const float sx = p.body.girdle_ws(rig, 0).x + p.body.facing * shoulder.x;
    const float ahead = p.body.facing * p.in.speed * kShoulderLookAhead;
    const float half = 0.05f * rig.hip_height;
    const float top = ground + rig.front_slack + 0.6f * shoulder.x;  // the most a turn gets over
    if (auto below = ground_below(p.ctx.level, std::min(sx, sx + ahead) - half, std::max(sx, sx + ahead) + half, top,
                                  top - ground + shoulder.x)) {
      const float rise = below->height_ws - ground - rig.front_slack;
      if (rise > 0.0f) *target_pitch = std::asin(std::min(rise / shoulder.x, 0.6f));
    }
  }
  *target_pitch -= p.in.pitch_down;
  const glm::vec2 d = rig.girdles.front().joint_ms - root_rest;
  *target_root = height.front() - rotate(d, *target_pitch + angle_extra).y;
}

// The ground a legless body lies on over [lo, hi] (world x): the highest box top under it no
// higher than a hip above the root, and of those only what it can crawl onto from the ground
// under its root, riser by riser, and what it lies on now (GroundProfile::climbable_top, no
// riser higher than AnimRig::crawl_climb): a level's end wall ahead of a whale, lower than its
// root, is a wall, not ground it rides up onto. `lift`: how far the body is held above its
// resting height. Where nothing is found, the ground it rests on now.
float legless_ground(const AnimContext& ctx, const BodyFrame& body, float lo, float hi, float lift) {
  const AnimRig& rig = ctx.rig;
  const float resting = body.root_y_ws - rig.root_rest_y - lift;
  auto hit = ground_below(ctx.level, lo, hi, body.root_y_ws + rig.hip_height, rig.scale.search_depth);
  if (!hit) return resting;
  const float climbable = ctx.ground.climbable_top(body.x_ws, lo, hi, rig.body_lo_ws(body.x_ws, body.facing),
                                                   rig.body_hi_ws(body.x_ws, body.facing), resting, rig.crawl_climb);
  return climbable < hit->height_ws ? climbable : hit->height_ws;  // (NaN: the profile cannot tell)
}

// The bob's dip (bob < 0) below the root height `base`, eased into the room the trunk has over
// what lies under it: past kBobFreeOfTrunkRoom of that room the dip slows into the rest of it,
// where the trunk clamp's floor would stop it dead (random creature 5's hop landed its ribs on
// that floor at 0.7 m/s every stride, 2.7 g).
float ease_dip_over_trunk(const AnimContext& ctx, BodyFrame body, float base, float bob) {
  const AnimRig& rig = ctx.rig;
  if (!(bob < 0.0f) || rig.trunk.empty() || rig.girdles.empty()) return bob;
  const glm::vec2 pivot = body.girdle_ws(rig, static_cast<int>(rig.girdles.size()) - 1);
  auto into = [&](float dip) {  // how far the trunk would be in what lies under it
    body.root_y_ws = base - dip;
    return trunk_need(ctx, body, 0.0f, pivot).raise;
  };
  // One look, at twice the dip: no trunk in anything there leaves the dip within the free share
  // (one look a tick: asked at the dip first, then at twice it, the trunk's need doubled the
  // horse's share of trunk_need, 15 % -> 26 % of its tick).
  const float dip = -bob;
  const float in = into(dip / kBobFreeOfTrunkRoom);
  if (!(in > 0.0f)) return bob;
  const float room = dip / kBobFreeOfTrunkRoom - in;
  const float free = kBobFreeOfTrunkRoom * room;
  if (!(room > 0.0f) || dip <= free) return bob;
  return -(free + (room - free) * std::tanh((dip - free) / (room - free)));
}

}  // namespace

// [SECTION] place_body --------------------------------------------------------------------------

void place_body(const AnimContext& ctx, const PlacementInputs& in, const FootSet& feet, TickHandoff& handoff, BodyFrame& body,
                BodyState& state) {
  std::fill(handoff.release_next.begin(), handoff.release_next.end(), 0);
  Placement p{ctx, in, feet, body, state, handoff.waiting, &handoff.release_next};
  handoff.trunk_left_in = false;
  p.trunk_left_in = &handoff.trunk_left_in;
  const AnimRig& rig = ctx.rig;
  const float old_root = body.root_y_ws;
  body.flex = in.flex;
  float target_root = body.root_y_ws, target_pitch = 0.0f;
  const size_t n = rig.girdles.size();
  // Scratch per girdle (a creature has a few), one thread-local lookup for all.
  thread_local struct {
    std::vector<float> height, need, room, fold, swing_up;
  } scratch;
  auto& [height, need, room, fold, swing_up] = scratch;
  if (height.size() != n) {
    for (std::vector<float>* v : {&height, &need, &room, &fold, &swing_up}) v->resize(n);
  }
  if (rig.girdles.empty()) {
    // Legless: follow the highest ground under the body that it can crawl onto (legless_ground:
    // not a wall it has come up to), lifted lately so that the wave keeps
    // the body out of the ground (held there, settling back slowly, rather than pulled down
    // and lifted again every tick).
    // The span looks kLeglessLookAhead seconds ahead, so that at speed the body has risen to a
    // step by the time it reaches it (the root height is smoothed).
    // On level ground the wave needs the same lift every wave: it settles slower there.
    const float ahead = body.facing * in.speed * kLeglessLookAhead;
    const float lo = rig.body_lo_ws(body.x_ws, body.facing) + std::min(ahead, 0.0f);
    const float hi = rig.body_hi_ws(body.x_ws, body.facing) + std::max(ahead, 0.0f);
    const float ground = legless_ground(ctx, body, lo, hi, state.body_lift);
    float level_height;
    const bool level = ctx.ground.spans(lo, hi) && ctx.ground.level_over(lo, hi, &level_height);
    if (in.dt > 0.0f && level && state.lift_hold > 0.0f) {
      state.lift_hold -= std::max(std::fabs(in.speed) / std::max(rig.body_half_length, 0.05f), 1.0f / kLeglessLiftHoldMax) * in.dt;
    } else if (in.dt > 0.0f) {
      state.body_lift *= std::exp(-(level ? kLeglessLiftSettleLevel : kLeglessLiftSettle) * in.dt);
    }
    target_root = ground + rig.root_rest_y + state.body_lift;
  } else {
    girdle_heights(p, height);
    body_target(p, height, &target_root, &target_pitch);
  }
  // The bob's part of the targets (and the flexion's, which moves the girdles as a bob would):
  // the same targets without them.
  float bob_root = 0.0f, bob_pitch = 0.0f;
  if (!rig.girdles.empty() && (!in.bob.empty() || body.flex != 0.0f)) {
    for (size_t g = 0; g < n && g < in.bob.size(); ++g) height[g] -= in.bob[g];
    float root0 = target_root, pitch0 = 0.0f;
    body.flex = 0.0f;
    body_target(p, height, &root0, &pitch0);
    body.flex = in.flex;
    bob_root = target_root - root0, bob_pitch = target_pitch - pitch0;
    target_root = root0, target_pitch = pitch0;
  }
  const bool snap = in.dt <= 0.0f;  // (a standing body placed at once)
  // What the knee clamp lately raised the body over level ground in a steady gait stays in its
  // target (a body eased back down to the target every flight phase had its sprawling knees
  // raise it 1.9 cm in a tick at each touch-down: random creature 47, 5.7 g running). Off level
  // ground, standing, crouched for a jump or landing, none.
  bool steady = false;
  if (!rig.girdles.empty()) {
    const float lo = rig.body_lo_ws(body.x_ws, body.facing), hi = rig.body_hi_ws(body.x_ws, body.facing);
    float level_height;
    steady = !snap && in.stepping && in.crouch == 0.0f && std::isnan(in.root) && ctx.ground.spans(lo, hi) &&
             ctx.ground.level_over(lo, hi, &level_height);
    state.knee_lift = steady ? state.knee_lift * std::exp(-kKneeLiftSettle * in.dt) : 0.0f;
    target_root += state.knee_lift;
  }
  bob_root = approach(state.bob_root, bob_root, snap ? 0.0f : in.keep_bob);
  bob_pitch = approach(state.bob_pitch, bob_pitch, snap ? 0.0f : in.keep_bob);
  body.pitch = approach(body.pitch - state.bob_pitch, target_pitch, snap ? 0.0f : in.keep_pitch) + bob_pitch;
  state.pitch_target = target_pitch + bob_pitch;
  if (std::isnan(in.root)) {
    const float base = approach(body.root_y_ws - state.bob_root, target_root, snap ? 0.0f : in.keep_root);
    bob_root = ease_dip_over_trunk(ctx, body, base, bob_root);
    body.root_y_ws = base + bob_root;
  } else {
    body.root_y_ws = in.root, bob_root = 0.0f;  // a landing's descent
  }
  state.bob_root = bob_root, state.bob_pitch = bob_pitch;

  keep_stance_legs_in_reach(p, need, room);
  keep_stance_legs_unfolded(p, fold, room);
  const float unkneed = body.root_y_ws;
  keep_knees_off_ground(p, need, swing_up, room);
  if (steady) state.knee_lift += body.root_y_ws - unkneed;
  pitch_for_front_shoulder(p);
  keep_body_out_of_ground(p, rig.girdles.empty() ? 0.0f : std::max(old_root - body.root_y_ws, 0.0f), room);
  release_overstretched_feet(p);
  state.root_vy = in.dt > 0.0f ? (body.root_y_ws - old_root) / in.dt : 0.0f;
}

void keep_stance_feet_in_reach(const AnimContext& ctx, const PlacementInputs& in, const FootSet& feet, TickHandoff& handoff,
                               BodyFrame& body, BodyState& state) {
  if (ctx.rig.girdles.empty()) return;
  Placement p{ctx, in, feet, body, state, handoff.waiting, &handoff.release_next};
  thread_local std::vector<float> need, room;
  need.resize(ctx.rig.girdles.size());
  room.resize(ctx.rig.girdles.size());
  keep_stance_legs_in_reach(p, need, room);
  release_overstretched_feet(p);
}

float standing_root(const AnimContext& ctx, const PlacementInputs& in, const FootSet& feet, const TickHandoff& handoff,
                    const BodyFrame& body) {
  const AnimRig& rig = ctx.rig;
  if (rig.girdles.empty()) {
    return legless_ground(ctx, body, rig.body_lo_ws(body.x_ws, body.facing), rig.body_hi_ws(body.x_ws, body.facing), 0.0f) +
           rig.root_rest_y;
  }
  BodyFrame frame = body;
  BodyState state;
  Placement p{ctx, in, feet, frame, state, handoff.waiting};
  thread_local std::vector<float> height;
  height.resize(rig.girdles.size());
  girdle_heights(p, height);
  float root = body.root_y_ws, pitch = 0.0f;
  body_target(p, height, &root, &pitch);
  return root;
}


// [SECTION] the body's other transitions ----------------------------------------------------------

void reset_body(float x, float root_y, int facing, BodyFrame& body, BodyState& state) {
  body.facing = facing < 0 ? -1 : 1;
  body.x_ws = x;
  body.lean = body.pitch = body.flex = 0.0f;
  body.root_y_ws = root_y;
  state.root_vy = state.body_lift = state.lift_hold = 0.0f;
  state.bob_root = state.bob_pitch = 0.0f;
}

void mirror_body(const AnimRig& rig, const std::vector<Mat2x3>& model_fs, BodyFrame& body) {
  if (!rig.girdles.empty()) {
    // The front girdle comes to stand where the back one stands and the back one where the
    // front one stands, each as high over that ground as it stands now over its own (by their
    // rest heights): a body pitched down a ledge turns along it, and one turned on level
    // ground stands as before. (Kept at its pitch and shifted by the rest girdles' x, a
    // stegosaurus turned pitched 40° down drops.json's 2 m ledge put its new front girdle
    // half a metre out over the lower floor: its forefeet swung down there and a stance foot
    // slid 86 cm.)
    const int back = static_cast<int>(rig.girdles.size()) - 1;
    const glm::vec2 front_ws = body.girdle_ws(rig, 0), back_ws = body.girdle_ws(rig, back);
    const float rest_rise = rig.girdles.front().rest_height - rig.girdles[back].rest_height;
    const glm::vec2 along = body.girdle_ms(rig, 0) - body.girdle_ms(rig, back);
    const float span = glm::length(along);
    body.facing = -body.facing;
    body.lean = 0.0f;
    if (span > 1e-4f) {
      const float rise = back_ws.y - front_ws.y + 2.0f * rest_rise;
      body.pitch = std::asin(std::clamp(rise / span, -0.95f, 0.95f)) - std::atan2(along.y, along.x);
    }
    const glm::vec2 now = body.girdle_ws(rig, 0);
    body.x_ws += back_ws.x - now.x;
    body.root_y_ws += back_ws.y + rest_rise - now.y;
    return;
  }
  // A legless body keeps the stretch of ground it lies on as it lies now (its tail comes to lie
  // where its head was, not swung into the wall its head was blocked at; a long neck laid along
  // the ground reaches further than at rest).
  float shift = 0.0f;
  if (!model_fs.empty()) {
    float lo = 0.0f, hi = 0.0f;
    for (int b = 0; b < rig.skeleton.bone_count(); ++b) {
      for (float x : {bone_start(model_fs[b]).x, bone_end(model_fs[b], rig.skeleton.length(b)).x}) {
        lo = std::min(lo, x);
        hi = std::max(hi, x);
      }
    }
    shift = lo + hi;
  }
  body.x_ws += body.facing * shift;
  body.facing = -body.facing;
  body.lean = 0.0f;
}

void lean_body(float lean, float keep, BodyFrame& body) { body.lean = approach(body.lean, lean, keep); }

void move_body(float dx, BodyFrame& body) { body.x_ws += dx; }

void fly_body(float root_y, float vy, float keep_level, BodyFrame& body, BodyState& state) {
  body.root_y_ws = root_y;
  body.pitch = approach(body.pitch, 0.0f, keep_level);
  body.lean = approach(body.lean, 0.0f, keep_level);
  body.flex = approach(body.flex, 0.0f, keep_level);
  state.root_vy = vy;
  state.bob_root = state.bob_pitch = 0.0f;
}

namespace {

// Turns the body about its front girdle so that girdle `g` rises by dy.
void tip_about_front(const AnimRig& rig, int g, float dy, BodyFrame& body) {
  const glm::vec2 front = body.girdle_ms(rig, 0), joint = body.girdle_ms(rig, g);
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

}  // namespace

// A falling trunk lands on the ground (rest_body_on_ground) only while every girdle is within
// this many of its rest heights above the ground under it.
constexpr float kTrunkLandsOverGroundOfRest = 1.5f;

bool rest_body_on_ground(const AnimContext& ctx, float floor, BodyFrame& body) {
  const AnimRig& rig = ctx.rig;
  if (rig.girdles.empty()) {
    // Looked for from up to half a body length above the root (no higher than the ledge it
    // left): a fast fall passes a belly's height in a tick.
    auto hit = ground_below(ctx.level, rig.body_lo_ws(body.x_ws, body.facing), rig.body_hi_ws(body.x_ws, body.facing),
                            std::min(body.root_y_ws + std::max(0.5f * rig.hip_height, rig.body_half_length), floor),
                            ctx.rig.scale.search_depth + rig.body_half_length);
    if (!hit || hit->height_ws + rig.root_rest_y <= body.root_y_ws) return false;
    body.root_y_ws = hit->height_ws + rig.root_rest_y;
    return true;
  }
  // Each girdle keeps out of the ground as clamp 5 keeps it (kGirdleKeepOutOfRest of its rest
  // height above the ground within kGirdleKeepOutHalfOfRest of it).
  bool landed = false, over_ground = true;
  for (int g = static_cast<int>(rig.girdles.size()) - 1; g >= 0; --g) {
    const glm::vec2 joint = body.girdle_ws(rig, g);
    const float rest = rig.girdles[g].rest_height;
    const float half = kGirdleKeepOutHalfOfRest * rest;
    auto hit = ground_below(ctx.level, joint.x - half, joint.x + half, joint.y + 0.5f * rest, ctx.rig.scale.search_depth);
    over_ground = over_ground && hit && joint.y - hit->height_ws <= kTrunkLandsOverGroundOfRest * rest;
    if (!hit) continue;
    const float need = hit->height_ws + kGirdleKeepOutOfRest * rest - joint.y;
    if (need <= 0.0f) continue;
    if (hit->height_ws >= floor && g > 0) {
      tip_about_front(rig, g, need, body);
    } else {
      body.root_y_ws += need;
      landed = true;
    }
  }
  // The trunk lands too: a chest or head hanging below the hips (a long neck, a body sloping
  // to short forelegs) comes down on the ground before the feet do, and lies on it (random
  // creature 28's chest went 0.54 m into drops.json's floor while its hind feet reached down).
  // Only over ground its legs are about to stand on: a head meeting the far side of a pit the
  // body falls into is the wall sweep's (go_back_from_face), not a landing.
  if (!over_ground) return landed;
  const placement::TrunkNeed trunk = placement::trunk_need(ctx, body, 0.0f, body.girdle_ws(rig, 0));
  if (trunk.raise > 0.0f) {
    body.root_y_ws += trunk.raise;
    landed = true;
  }
  return landed;
}

void raise_body(float raise, BodyFrame& body, BodyState& state) {
  body.root_y_ws += raise;
  state.body_lift += raise;
  state.lift_hold = 1.0f;
}

}  // namespace ossa::anim
