// Body placement's clamps, in their order (body_placement.h), and the girdle moves they make.

#include <algorithm>
#include <cmath>

#include "ossa/anim/anim_math.h"
#include "ossa/anim/animator_params.h"
#include "ossa/anim/body_motion.h"
#include "ossa/anim/body_placement_internal.h"
#include "ossa/anim/foothold.h"
#include "ossa/anim/leg_geometry.h"
#include "ossa/math/two_bone_ik.h"

namespace ossa::anim::placement {

// Moves girdle g's joint up by dy, turning the body about the girdle at the other end.
void move_girdle(Placement& p, int g, float dy) {
  const AnimRig& rig = p.ctx.rig;
  BodyFrame& body = p.body;
  const int n = static_cast<int>(rig.girdles.size());
  if (n < 2 || (g != 0 && g != n - 1)) {
    body.root_y_ws += dy;
    return;
  }
  // Turn the body about the girdle at the other end (o), which stays put; whatever a turn
  // within the pitch limits (per tick and overall) cannot give, the whole body moves.
  const glm::vec2 root_rest(0.0f, rig.root_rest_y);
  const glm::vec2 o = body.girdle_ms(rig, g == 0 ? n - 1 : 0) - root_rest;
  const glm::vec2 v = body.girdle_ms(rig, g) - root_rest - o;
  const float len = std::sqrt(v.x * v.x + v.y * v.y);
  const glm::vec2 v_before = body.rotate_body(v), o_before = body.rotate_body(o);
  if (len > 1e-4f) {
    const float phi = fast_atan2(v.y, v.x), a = body.pitch + body.lean;
    const float s = std::asin(std::clamp((v_before.y + dy) / len, -0.95f, 0.95f));
    const float turned = (std::cos(a + phi) >= 0.0f ? s : kPi - s) - phi;
    const float step = std::clamp(wrap_angle(turned - a), -kMaxPitchStep, kMaxPitchStep);
    float lo = std::max(p.state.pitch_target - kMaxPitchOff, -kMaxPitch);
    float hi = std::min(p.state.pitch_target + kMaxPitchOff, kMaxPitch);
    if (p.in.turning) {
      // On a turn's tick a body the turn left further off turns no further off, rather than
      // at once into the bounds: that would swing its girdles off the feet just handed over.
      lo = std::min(lo, body.pitch);
      hi = std::max(hi, body.pitch);
    }
    body.pitch = std::clamp(body.pitch + step, lo, hi);
  }
  const float moved = body.rotate_body(v).y - v_before.y;
  body.root_y_ws += o_before.y - body.rotate_body(o).y + (dy - moved);
}

// The least height of a girdle joint at joint_ws (rest height `rest`) out of the ground:
// kGirdleKeepOutOfRest of its rest height above the highest ground within
// kGirdleKeepOutHalfOfRest of it either side, the ground as far again beyond counting less and
// less (keep_out_height), so that a bump's edge coming into reach as the body moves or turns
// does not pop the body up by its height. Ground is looked for from half a rest height (plus
// `extra`) above the joint; -1e30 where there is none.
// The highest ground a girdle's keep-out counts: ground more than kKeepOutStepsOfClimb
// climbable steps above the ground the girdle stands over is a wall (the wall sweep stops the
// body at it), not ground to lift the body over: a creature turned round below a ledge would
// otherwise be lifted by the ledge's height as its shoulders near the face.
float girdle_keep_out_top(const AnimContext& ctx, glm::vec2 joint_ws, float rest, float extra) {
  const float step = ctx.params.max_step_up * ctx.rig.climb_height;
  return std::min(joint_ws.y + 0.5f * rest, joint_ws.y - rest * ctx.params.stance_height + kKeepOutStepsOfClimb * step) + extra;
}

float girdle_keep_out(const AnimContext& ctx, glm::vec2 joint_ws, float rest, float extra) {
  return keep_out_height(ctx.level, joint_ws.x, kGirdleKeepOutHalfOfRest * rest, kGirdleKeepOutOfRest * rest,
                         kKeepOutFadeOfRest * rest, girdle_keep_out_top(ctx, joint_ws, rest, extra), ctx.rig.scale.search_depth, ctx.hits);
}

// [SECTION] clamps, in their order ------------------------------------------------------------

// 1. Never over-extend a leg on the ground: lower its girdle (hard clamp, no smoothing; again
// when that moved it, as a rolling foot's reach depends on where the joint is). The end
// girdles turn the body about each other, so a hind leg left on a lower step pitches the body
// up instead of pulling the shoulders down into the steps ahead. Returns how far each girdle
// may still rise with its feet in reach (room).
void keep_stance_legs_in_reach(Placement& p, std::vector<float>& need, std::vector<float>& room) {
  const AnimRig& rig = p.ctx.rig;
  const size_t n_groups = rig.girdles.size();
  for (int pass = 0; pass < 3; ++pass) {
    bool beyond = false;  // a stance foot out of reach even level with the joint
    for (size_t g = 0; g < n_groups; ++g) {  // (one loop: no call to memset for two floats)
      need[g] = 0.0f;
      room[g] = 1e30f;
    }
    GirdleJointFs joints;
    for (size_t i = 0; i < rig.legs.size(); ++i) {
      const RigLeg& info = rig.legs[i];
      const FootState& f = p.feet.of_leg(static_cast<int>(i));
      // On the turn tick, swinging feet (taken over by other legs) must stay in reach too; not
      // one hanging over a drop, tucked (turn_feet: the pig turned round for a jump at the end
      // of drops.json's floor, its new hind feet hanging 19 cm below the floor's top over the
      // pit, was drawn down 39 cm after them and a rib went 9.3 cm into the floor's edge).
      if (f.state != LegState::kStance && !(p.in.turning && !f.easing && !f.air)) continue;
      const glm::vec2 joint = joints.of(rig, p.body, info.girdle);
      float r;
      const glm::vec2 anchor = leg_anchor(p.ctx, p.body, static_cast<int>(i), p.body.to_fs(f.pos_ws), joint,
                                          f.state == LegState::kStance ? f.stance_clear : f.swing_clear, &r);
      const float dx = std::fabs(anchor.x - joint.x);
      if (dx >= r) {
        beyond = beyond || f.state == LegState::kStance;
        continue;
      }
      const float allowed = anchor.y + reach_across(r, dx);
      // (A joint further below the foot than the leg reaches is out of reach too; a foot within
      // kReachCheckSlack of its reach is left to clamp 6's own test, whose rounding differs.)
      beyond = beyond || (f.state == LegState::kStance &&
                          (2.0f * anchor.y - allowed > joint.y - kReachCheckSlack || joint.y > allowed - kReachCheckSlack));
      need[info.girdle] = std::max(need[info.girdle], joint.y - allowed);
      room[info.girdle] = std::min(room[info.girdle], allowed - joint.y);
      // A foot left behind and below (stairs) that drags the body down lifts on the next tick
      // rather than fold the other legs into the step ahead.
      if (pass == 0 && f.state == LegState::kStance && anchor.x < joint.x &&
          joint.y - allowed > kDragLiftOfRest * rig.girdles[info.girdle].rest_height) {
        (*p.release)[p.feet.foot_of_leg[i]] = 1;
      }
    }
    // Turning the body moves the other girdle's joint sideways a little: the last pass lowers
    // the whole body, which keeps every joint's x.
    float most = 0.0f;
    for (float d : need) most = std::max(most, d);
    if (most <= 0.0f) {
      // Every stance foot within reach (need ≤ 0 is allowed ≥ joint.y: |anchor - joint| ≤ r).
      p.reach_checked = !beyond;
      p.checked_root = p.body.root_y_ws;
      p.checked_pitch = p.body.pitch;
      break;
    }
    for (size_t g = 0; g < n_groups; ++g) {
      if (need[g] <= 0.0f) continue;
      if (pass < 2) move_girdle(p, static_cast<int>(g), -need[g]);
      room[g] += need[g];
    }
    if (pass == 2) p.body.root_y_ws -= most;
  }
}

// 2. Nor fold a leg on the ground tighter than it can (short legs with long shins on a low
// body, a hind foot stepped up a ledge under its joint): raise its girdle until each stance
// ankle is at least the folded length away. The end girdles turn the body about each other,
// as in 1, so that the other end's feet stay where they are.
void keep_stance_legs_unfolded(Placement& p, std::vector<float>& fold_raise, std::vector<float>& room) {
  const AnimRig& rig = p.ctx.rig;
  bool any = false;  // fold_raise holds this tick's raises (filled at the first)
  GirdleJointFs joints;
  for (size_t i = 0; i < rig.legs.size(); ++i) {
    const FootState& f = p.feet.of_leg(static_cast<int>(i));
    if (f.state != LegState::kStance) continue;
    const float fold = rig.legs[i].fold;
    const glm::vec2 joint = joints.of(rig, p.body, rig.legs[i].girdle);
    // The ankle lies within a foot's length of the contact point.
    if (glm::length(p.body.to_fs(f.pos_ws) - joint) - rig.legs[i].foot_span >= fold) continue;
    glm::vec2 dir;
    // (The ankle where the foot holds its angle: how far the leg would fold, not the roll that
    // keeps it from folding past its least reach.)
    const glm::vec2 ankle =
        leg_ankle(p.ctx, p.body, static_cast<int>(i), p.body.to_fs(f.pos_ws), joint, true, f.stance_clear, &dir, nullptr, false);
    const float dx = std::fabs(ankle.x - joint.x);
    if (dx < fold) {
      if (!any) std::fill(fold_raise.begin(), fold_raise.end(), 0.0f);
      any = true;
      float& raise = fold_raise[rig.legs[i].girdle];
      raise = std::max(raise, ankle.y + reach_across(fold, dx) - joint.y);
    }
  }
  if (!any) return;
  // The whole body rises when every girdle has the room; else the folded girdle alone.
  float most = 0.0f, least_room = 1e30f;
  for (size_t g = 0; g < fold_raise.size(); ++g) {
    most = std::max(most, fold_raise[g]);
    least_room = std::min(least_room, room[g]);
  }
  if (most <= 0.0f) return;
  if (most <= least_room) {
    p.body.root_y_ws += most;
    for (float& r : room) r = std::max(r - most, 0.0f);
    return;
  }
  for (size_t g = 0; g < fold_raise.size(); ++g) {
    if (fold_raise[g] <= 0.0f) continue;
    // What each girdle rises comes off its room.
    for (size_t o = 0; o < room.size(); ++o) room[o] += p.body.girdle_ws(rig, static_cast<int>(o)).y;
    move_girdle(p, static_cast<int>(g), fold_raise[g]);
    for (size_t o = 0; o < room.size(); ++o) room[o] = std::max(room[o] - p.body.girdle_ws(rig, static_cast<int>(o)).y, 0.0f);
  }
}

// How far leg i's stance foot is beyond its leg's reach (≤ 0: in reach; -1e30 for a leg not
// on the ground).
float stance_excess(const Placement& p, size_t i, GirdleJointFs& joints) {
  const AnimRig& rig = p.ctx.rig;
  const FootState& f = p.feet.of_leg(static_cast<int>(i));
  if (f.state != LegState::kStance) return -1e30f;
  return leg_overreach(p.ctx, p.body, static_cast<int>(i), f, joints.of(rig, p.body, rig.legs[i].girdle));
}

// How far the stance foot furthest out of its leg's reach is beyond it (≤ 0: all in reach).
float stance_reach_excess(const Placement& p) {
  float most = -1e30f;
  GirdleJointFs joints;
  for (size_t i = 0; i < p.ctx.rig.legs.size(); ++i) most = std::max(most, stance_excess(p, i, joints));
  return most;
}

// How far a leg's thigh (hip-knee) or shin (knee-heel) cuts across the edge of a step
// (vertically, metres; raise_to_clear). A joint itself at a box's face, or in it, is the body's
// business, not its thigh's: a blocked body's pitch easing turned the 2 m-frame rock hyrax's
// shoulders forward onto drops.json's 0.7 m riser, and lifting the body by the riser's height
// above them took the forefeet 16 cm off the ground in a tick. The face push-back moves the
// body out.
float chain_crossing(const Level& level, std::vector<int>& hits, glm::vec2 hip, glm::vec2 knee, glm::vec2 heel) {
  const bool joint_in = level.overlaps(Box{hip - glm::vec2(1e-4f), hip + glm::vec2(1e-4f)});
  return std::max(joint_in ? 0.0f : raise_to_clear(hip, knee, level, hits), raise_to_clear(knee, heel, level, hits));
}

// The most any stance leg's thigh or shin cuts across the edge of a step as the body is placed
// now (chain_crossing).
float stance_crossing(const Placement& p) {
  const AnimRig& rig = p.ctx.rig;
  float most = 0.0f;
  GirdleJointFs joints;
  for (size_t i = 0; i < rig.legs.size(); ++i) {
    const FootState& f = p.feet.of_leg(static_cast<int>(i));
    if (f.state != LegState::kStance) continue;
    const RigLeg& info = rig.legs[i];
    const glm::vec2 joint = joints.of(rig, p.body, info.girdle);
    glm::vec2 dir;
    const glm::vec2 ankle = leg_ankle(p.ctx, p.body, static_cast<int>(i), p.body.to_fs(f.pos_ws), joint, true, f.stance_clear, &dir, nullptr);
    const TwoBoneIkResult ik = solve_two_bone_ik_directions(joint, info.upper, info.lower, ankle, info.bend);
    most = std::max(most, chain_crossing(p.ctx.level, p.ctx.hits, p.body.to_ws(joint), p.body.to_ws(ik.middle), p.body.to_ws(ik.end)));
  }
  return most;
}

// 3. Nor kneel: a leg folded so far that its knee would touch the ground (sprawling legs on a
// low body, or lifted in a swing) raises its girdle until the knee clears the ground under
// it. A swinging leg's knee raises it only as far as the legs on the ground allow (their feet
// must not slide); past that the swing itself lifts and tucks the leg (leg IK). With the foot
// in place a raised joint lifts the knee by less than itself: up to kKneePasses passes, as
// long as some girdle moves.
// A stance raise is scaled by what the last one gained only when it gained more than this
// fraction of itself, and to at most this many times the need. (At 5 % the harbour seal's
// shin across drops.json's 1 m ledge, lifted by 2 % of each raise, stayed 1.01 mm in.)
constexpr float kKneeSecantLeast = 0.01f, kKneeSecantMost = 8.0f;
void keep_knees_off_ground(Placement& p, std::vector<float>& stance_up, std::vector<float>& swing_up, std::vector<float>& room) {
  const AnimRig& rig = p.ctx.rig;
  const Level& level = p.ctx.level;
  // How far each stance leg's thigh or shin still crossed the edge of a step on the last pass
  // (vertically, metres).
  thread_local std::vector<float> crossed;
  // Per girdle: a stance thigh's or shin's crossing of a step's edge this pass (its raise; a
  // shin across a small tread's corner: corner_crossing, raised within the stance legs' reach
  // as a swinging knee is), and the raise for one the last pass made (0: none) and the need it
  // was made for.
  thread_local std::vector<float> crossing, corner_crossing, last_up, last_need;
  last_up.assign(rig.girdles.size(), 0.0f);
  last_need.assign(rig.girdles.size(), 0.0f);
  for (int pass = 0; pass < kKneePasses; ++pass) {
    crossed.assign(rig.legs.size(), 0.0f);
    crossing.assign(rig.girdles.size(), 0.0f);
    corner_crossing.assign(rig.girdles.size(), 0.0f);
    std::fill(stance_up.begin(), stance_up.end(), 0.0f);
    std::fill(swing_up.begin(), swing_up.end(), 0.0f);
    GirdleJointFs joints;
    for (size_t i = 0; i < rig.legs.size(); ++i) {
      const FootState& f = p.feet.of_leg(static_cast<int>(i));
      const bool stance = f.state == LegState::kStance;
      const RigLeg& info = rig.legs[i];
      const glm::vec2 joint = joints.of(rig, p.body, info.girdle);
      const float margin = kKneeMarginOfReach * info.reach;
      // The knee is no lower than a thigh below the joint nor a shin below the ankle: cheap
      // tests before the IK (unless steps rise near the foot, or any ground above it: a shin
      // lying low across the corner of the tread a foot stepped down from cuts it, however
      // small the step).
      const Clearance& near = stance ? f.stance_reach_clear : f.swing_clear;
      const bool steps_near = !near.clear_above(f.pos_ws.y + margin);
      const bool corner_near = stance && !steps_near && !near.clear_above(f.pos_ws.y);
      if (!steps_near && !corner_near && joint.y - info.upper > f.pos_ws.y + margin) continue;
      glm::vec2 dir;
      const glm::vec2 ankle = leg_ankle(p.ctx, p.body, static_cast<int>(i), p.body.to_fs(f.pos_ws), joint, true,
                                        stance ? f.stance_clear : f.swing_clear, &dir, nullptr, stance);
      if (!steps_near && !corner_near && ankle.y - info.lower > f.pos_ws.y + margin) continue;
      const TwoBoneIkResult ik = solve_two_bone_ik_directions(joint, info.upper, info.lower, ankle, info.bend);
      const glm::vec2 knee = p.body.to_ws(ik.middle);
      float& up = stance ? stance_up[info.girdle] : swing_up[info.girdle];
      // (The ground within kKneeHalfWidth of the knee, fading beyond: a knee beside a riser
      // is not lifted by its height when a turn moves it a millimetre.)
      if (const float ground = keep_out_height(level, knee.x, kKneeHalfWidth, margin, info.reach, knee.y + info.reach,
                                               2.0f * info.reach, p.ctx.hits);
          ground > -1e29f) {
        // Into the ground: out at once. Only within the margin of the ground its foot stands
        // on (no step near): eased at the root's own rate, so that a knee coming near the
        // ground at a touch-down does not step the body up; once a tick (eased again on every
        // pass, six passes raised by half the need a tick: random creature 47's sprawling
        // knee, 4.45 g running; 4.1 g now, the rest is its knee going into the ground).
        float need = ground - knee.y;
        // A stance knee beside a riser taller than the leg reaches (clear of it, at its face)
        // rises no further than the stance legs reach: a 10 g bird blocked at a 7 cm riser,
        // its knee at the face, was lifted 2.2 cm in a tick and drawn back down by its
        // legs, every tenth of a second, its feet 14 mm off their footholds.
        if (stance && need > margin + room[info.girdle] && !level.point_inside(knee)) need = margin + room[info.girdle];
        const bool flat = !steps_near && !corner_near && ground - margin <= f.pos_ws.y + 1e-3f;
        const float ease = flat && p.in.dt > 0.0f ? (pass == 0 ? 1.0f - p.in.keep_root : 0.0f) : 1.0f;
        up = std::max(up, std::max(need - margin, need * ease));
      }
      // On steps a thigh or shin may cross the edge of a step beside the knee (a swinging leg
      // far back down a flight, say), as may a shin coming up to a foot on the edge of a ledge
      // from a knee below it. A shin across a small tread's corner raises its girdle only as
      // far as the stance legs reach (swing_up's limit), lest a foot slide.
      if (steps_near || corner_near || knee.y < f.pos_ws.y + margin) {
        const float cross = chain_crossing(level, p.ctx.hits, p.body.to_ws(joint), knee, p.body.to_ws(ik.end));
        float& cross_up = corner_near && knee.y >= f.pos_ws.y + margin ? swing_up[info.girdle] : up;
        cross_up = std::max(cross_up, cross);
        float& crossing_of = &cross_up == &stance_up[info.girdle] ? crossing[info.girdle] : corner_crossing[info.girdle];
        crossing_of = std::max(crossing_of, cross);
        // Only a foot left behind its girdle (it lifts soon anyway): a leading foot released
        // leaves the body to the feet behind, which the next raise stretches.
        if (stance && p.body.to_fs(f.pos_ws).x < joint.x) crossed[i] = cross;
      }
    }
    bool moved = false;
    for (size_t g = 0; g < rig.girdles.size(); ++g) {
      // A raise lifts a stance shin's crossing near its foot by much less than itself (the shin
      // turns about the ankle): from the last pass's raise and what it gained, the raise that
      // clears (a secant step), at most kKneeSecantMost times the need. (Raised by the need each
      // pass, the ichthyostega's forearm stood 2.4 mm across a block's corner after the last
      // pass as its forefoot stepped up.) Only where a crossing asks the raise: a knee's own
      // need on level ground is eased on purpose.
      // So too a shin across a tread's corner (the rabbit's forearm low over the corner of
      // slopes.json's top as its forefoot stepped just past it was lifted by a twentieth of
      // each raise, 1.46 mm in after the last pass).
      float stance = stance_up[g], swing = swing_up[g];
      const bool crossing_asks = stance > 0.0f && crossing[g] >= stance;
      const bool corner_asks = !crossing_asks && swing > stance && corner_crossing[g] >= swing;
      float& scaled = crossing_asks ? stance : swing;
      if ((crossing_asks || corner_asks) && last_up[g] > 0.0f && last_need[g] - scaled > kKneeSecantLeast * last_up[g]) {
        scaled = std::min(scaled * last_up[g] / (last_need[g] - scaled), kKneeSecantMost * scaled);
      }
      last_up[g] = 0.0f;
      const float up = std::min(std::max(stance, std::min(swing, room[g])), kMaxKneeRaiseOfHip * rig.hip_height);
      if (up <= 0.0f) continue;
      if (up > stance) {
        // A raised end girdle turns the body about the other one, whose joint moves sideways
        // a little: a swinging knee's raise must not take a stance foot out of reach, nor
        // straighten a stance leg across a step's edge (halved until it does not; a stance
        // knee's raise stands, and its foot lifts, clamp 6). (Random creature 40, a biped with a
        // 25 cm hip on stairs.json's 25 cm risers: a swinging knee at the face of the riser
        // ahead raised the body 15 cm in a tick, and the stance leg behind, its toe at the foot
        // of the riser it stood below, straightened with its ankle 5.7 mm into that riser.)
        const BodyFrame before = p.body;
        const float allowed = std::max(stance_reach_excess(p), 0.0f) + kSwingRaiseSlack;
        const float crossing_allowed = stance_crossing(p) + kSwingRaiseSlack;
        float tried = up;
        for (int k = 0; k < kSwingRaiseHalvings; ++k, tried *= 0.5f) {
          move_girdle(p, static_cast<int>(g), tried);
          if (stance_reach_excess(p) <= allowed && stance_crossing(p) <= crossing_allowed) break;
          p.body = before;
        }
        if (p.body.root_y_ws == before.root_y_ws && p.body.pitch == before.pitch) continue;
        room[g] = std::max(room[g] - tried, 0.0f);
        if (corner_asks) last_up[g] = tried, last_need[g] = swing_up[g];
        moved = true;
        continue;
      }
      move_girdle(p, static_cast<int>(g), up);
      room[g] = std::max(room[g] - up, 0.0f);
      if (crossing_asks) last_up[g] = up, last_need[g] = stance_up[g];
      moved = true;
    }
    if (!moved) break;
  }
  // A stance leg the raises left across an edge (a raise turns the body about its other end
  // and lifts the knee by less than itself; the other feet hold the body down: a hind foot left
  // on the edge of a ledge the body steps down from, its shin across the edge) lifts at the
  // next chance rather than stand in the step (clamp 6's hand-off). Only while the feet step:
  // a standing (or blocked) creature's released foot would restep at once, a slide.
  if (p.release == nullptr || !p.in.stepping) return;
  for (size_t i = 0; i < rig.legs.size(); ++i) {
    if (crossed[i] > kStanceCrossRelease) (*p.release)[p.feet.foot_of_leg[i]] = 1;
  }
}

// How far a shoulder at `shoulder` (world) must rise to keep kShoulderKeepOutOfHip above the
// ground under it (looked for from half a standing height, plus `extra`, above it).
float shoulder_need(const Placement& p, glm::vec2 shoulder, float extra) {
  const float hip = p.ctx.rig.hip_height;
  const float half = 0.05f * hip;
  auto below = ground_below(p.ctx.level, shoulder.x - half, shoulder.x + half, shoulder.y + 0.5f * hip + extra, p.ctx.rig.scale.search_depth);
  return below ? below->height_ws + kShoulderKeepOutOfHip * hip - shoulder.y : 0.0f;
}

// 4. The shoulder far ahead of a single girdle meeting a step: the body turns up about the
// girdle (the feet stay in reach) rather than rise (the pitch target follows more slowly).
void pitch_for_front_shoulder(Placement& p) {
  const AnimRig& rig = p.ctx.rig;
  if (!(rig.front_shoulder.x > 0.0f)) return;
  const glm::vec2 rel = rig.girdles.front().joint_ms - glm::vec2(0.0f, rig.root_rest_y);
  for (int pass = 0; pass < 2; ++pass) {
    const float need = shoulder_need(p, p.body.body_point_ws(rig, rig.girdles.front().joint_ms + rig.front_shoulder), 0.0f);
    if (need <= 0.0f) break;
    const float girdle_y = p.body.rotate_body(rel).y;
    p.body.pitch = std::min(p.body.pitch + std::asin(std::min(need / rig.front_shoulder.x, 0.9f)), kMaxPitch);
    p.body.root_y_ws += girdle_y - p.body.rotate_body(rel).y;
  }
}

// The trunk's bones (ribs, spine, neck, skull) cut no step either: how far the body must rise
// (lifted by `lift` already) so that each keeps kTrunkKeepOfHip clear of the boxes it is in.
// A bone needing kMaxTrunkRaiseOfHip or more meets a wall, which this clamp does not climb
// (the wall sweep stops the body there: its hull, its skull, and a trunk bone lying more than
// kMaxTrunkRaiseOfHip under a riser's top where it crosses it).
// The bones as at rest, the body placed as now; the skull's kept level.
constexpr float kTrunkKeepOfHip = 0.01f;  // (kMaxTrunkRaiseOfHip: body_motion.h)
// A trunk that sank into a box on this tick rises out of it whatever the legs reach, up to this
// many hip heights (keep_body_out_of_ground).
constexpr float kTrunkSinkOfHip = 0.05f;
// A body held by its hind girdle alone turns up for its trunk at most this many times a tick.
constexpr int kTrunkPitchPasses = 3;
TrunkNeed trunk_need(const AnimContext& ctx, const BodyFrame& body, float lift, glm::vec2 pivot_ws) {
  const AnimRig& rig = ctx.rig;
  if (rig.trunk.empty()) return {};
  const float hip = rig.hip_height, keep = kTrunkKeepOfHip * hip;
  // One look at the ground profile under the trunk's whole bound first (on flat ground and
  // away from steps, all the work there is): its rest bound turned with the body, widened by
  // the level skull's reach against the body's turn.
  glm::vec2 lo(1e30f), hi(-1e30f);
  for (glm::vec2 c : {rig.trunk_lo, rig.trunk_hi, glm::vec2(rig.trunk_lo.x, rig.trunk_hi.y), glm::vec2(rig.trunk_hi.x, rig.trunk_lo.y)}) {
    const glm::vec2 w = body.body_point_ws(rig, c + glm::vec2(0.0f, rig.root_rest_y), lift);
    lo = glm::min(lo, w);
    hi = glm::max(hi, w);
  }
  const bool head = rig.trunk_level_from < rig.trunk.size();
  if (head) {
    const float reach = rig.skeleton.length(rig.skull) + glm::length(rig.trunk_hi - rig.trunk_lo) * std::fabs(std::sin(body.pitch + body.lean));
    lo -= glm::vec2(reach);
    hi += glm::vec2(reach);
  }
  if (!ctx.ground.may_rise_above(lo.x, hi.x, lo.y - keep, hi.y + kMaxTrunkRaiseOfHip * hip)) return {};
  // The skull's segments hang from its joint where the body puts it, kept level.
  const glm::vec2 skull_ms = head ? bone_start(rig.model_rest[rig.skull]) : glm::vec2(0.0f);
  const glm::vec2 skull_fs = head ? body.to_fs(body.body_point_ws(rig, skull_ms, lift)) : glm::vec2(0.0f);
  auto point_ws = [&](size_t i, glm::vec2 p_ms) {
    return i < rig.trunk_level_from ? body.body_point_ws(rig, p_ms, lift) : body.to_ws(skull_fs + (p_ms - skull_ms));
  };
  const float pivot = body.to_fs(pivot_ws).x;
  // Over level ground under the whole trunk, a head low over it is its neck's business
  // (keep_head_clear lifts it there), not the body's: held up by its head at each landing, a
  // hopper carrying its head low stopped dead in the dip (random creature 39, 3.3 g).
  float level;
  const size_t n = head && rig.nod_bones[0] >= 0 && ctx.ground.spans(lo.x, hi.x) && ctx.ground.level_over(lo.x, hi.x, &level)
                       ? rig.trunk_level_from
                       : rig.trunk.size();
  TrunkNeed need;
  for (size_t i = 0; i < n; ++i) {
    const glm::vec2 a = point_ws(i, rig.trunk[i].a) - glm::vec2(0.0f, keep);
    const glm::vec2 b = point_ws(i, rig.trunk[i].b) - glm::vec2(0.0f, keep);
    if (!ctx.ground.may_rise_above(std::min(a.x, b.x), std::max(a.x, b.x), std::min(a.y, b.y), std::max(a.y, b.y) + kMaxTrunkRaiseOfHip * hip)) continue;
    const float n = raise_to_clear(a, b, ctx.level, ctx.hits);
    if (!(n > 0.0f) || n >= kMaxTrunkRaiseOfHip * hip) continue;
    need.raise = std::max(need.raise, n);
    const float ahead = std::max(body.to_fs(a).x, body.to_fs(b).x) - pivot;
    if (ahead > 0.1f * hip) need.pitch = std::max(need.pitch, std::asin(std::min(n / ahead, 0.9f)));
  }
  return need;
}

// 5. Whatever the legs ask, a girdle never sinks into the ground under it: it keeps an
// eighth of its standing height above the highest ground there (a leg may stretch, the body
// stays out). Ground the body came down past on this tick (`fell`) counts too (clamp 1 may
// pull it down further than the queries look up). Shoulders carrying arms, wings or fins too,
// and folded wings do not cut a step's corner (a wall, too high to rise over, is the wall
// sweep's business). Nor do the trunk's own bones (trunk_need), as far as the stance legs reach;
// a body its hind girdle alone holds up (a single girdle's, or one whose other girdles' feet
// are all off the ground) turns up about it for the rest.
void keep_body_out_of_ground(Placement& p, float fell, const std::vector<float>& room) {
  const AnimRig& rig = p.ctx.rig;
  // The trunk rises no further than every stance foot stays in reach (a body pitched down a
  // ledge, its feet below, would pull them off their footholds); standing, nor does the girdles'
  // margin.
  float least_room = 1e30f;
  for (float r : room) least_room = std::min(least_room, r);
  const bool standing = !p.in.stepping;
  float raise = 0.0f, tops = 0.0f;  // tops: the box tops under the joints alone
  for (size_t g = 0; g < rig.girdles.size(); ++g) {
    const glm::vec2 joint = p.body.girdle_ws(rig, static_cast<int>(g));
    const float rest = rig.girdles[g].rest_height;
    // Ground within the window (twice its half, where claims fade) no higher than the keep
    // below the joint cannot raise it: the ground profile says so without a level query.
    const float half = 2.0f * kGirdleKeepOutHalfOfRest * rest;
    const float top = girdle_keep_out_top(p.ctx, joint, rest, fell);
    if (!p.ctx.ground.may_rise_above(joint.x - half, joint.x + half, joint.y - kGirdleKeepOutOfRest * rest, top)) continue;
    raise = std::max(raise, girdle_keep_out(p.ctx, joint, rest, fell) - joint.y);
    if (standing) {
      tops = std::max(tops, keep_out_height(p.ctx.level, joint.x, kGirdleKeepOutHalfOfRest * rest, 0.0f, kNoFadeOfRest * rest, top,
                                            rig.scale.search_depth, p.ctx.hits) -
                                joint.y);
    }
  }
  // Standing, the girdles' margin over the boxes (and its fade beyond them) yields to the
  // stance legs' reach; the box tops under a joint do not. (The triceratops blocked at
  // default.json's 1.8 m post, its shoulders beside it, was held up by the post's margin while
  // its pitch eased down: a forefoot set down where the leg no longer reached stood 7.6 mm
  // short of its foothold and slid there a tick later.)
  if (standing && raise > 0.0f) raise = std::max(tops, std::min(raise, std::max(least_room, 0.0f)));
  auto keep_shoulder_out = [&](const RigLimb& limb) {
    raise = std::max(raise, shoulder_need(p, p.body.body_point_ws(rig, bone_start(rig.model_rest[limb.bones[0]])), fell));
  };
  for (const RigLimb& a : rig.outline_arms) keep_shoulder_out(a);
  for (const RigLimb& w : rig.outline_wings) keep_shoulder_out(w);
  for (const RigLimb& w : rig.outline_wings) {
    glm::vec2 a = p.body.body_point_ws(rig, bone_start(rig.model_rest[w.bones[0]]), raise);
    for (int b : w.bones) {
      const glm::vec2 e = p.body.body_point_ws(rig, bone_end(rig.model_rest[b], rig.skeleton.length(b)), raise);
      const float need = raise_to_clear(a, e, p.ctx.level, p.ctx.hits);
      if (need < 0.5f * rig.hip_height) raise += need;
      a = e;
    }
  }
  for (const RigLimb& f : rig.outline_fins) keep_shoulder_out(f);
  if (rig.trunk.empty()) {
    p.body.root_y_ws += raise;
    return;
  }
  const glm::vec2 pivot = p.body.girdle_ws(rig, static_cast<int>(rig.girdles.size()) - 1);
  TrunkNeed trunk = trunk_need(p.ctx, p.body, raise, pivot);
  // A body held by its hind girdle alone turns up about it too: a single girdle's, or one whose
  // other girdles have no foot on the ground (a quadruped's forefeet stepping down a ledge).
  bool hind_holds = true;
  for (size_t g = 0; g + 1 < rig.girdles.size(); ++g) hind_holds = hind_holds && !(room[g] < 1e29f);
  for (int pass = 0; pass < kTrunkPitchPasses && trunk.raise > least_room - raise && hind_holds && trunk.pitch > 0.0f;
       ++pass) {
    // More than the legs allow: the body turns up about the hind girdle instead (a biped's
    // chest over the stairs ahead, a tortoise's shell over the corner of the ledge its forefeet
    // step down: 2.1 cm in), the feet where they were. The turn for the deepest bone
    // may leave another in (a rib further back, which the turn raises less): again, up to
    // kTrunkPitchPasses turns (one left random creature 42's ribs 1-2 cm in the stair tops and
    // the tyrannosaurus's 2.2 cm in drops.json's start wall).
    const glm::vec2 rel = rig.girdles.back().joint_ms - glm::vec2(0.0f, rig.root_rest_y);
    const float girdle_y = p.body.rotate_body(rel).y;
    const float was = p.body.pitch;
    p.body.pitch = std::min(p.body.pitch + trunk.pitch, std::max(kMaxPitch, p.body.pitch));
    p.body.root_y_ws += girdle_y - p.body.rotate_body(rel).y;
    trunk = trunk_need(p.ctx, p.body, raise, pivot);
    if (p.body.pitch == was) break;  // at the steepest already
  }
  // What the legs' reach allows; but the body does not sink into a box it was clear of: a need
  // that only takes back this tick's descent is met whatever the legs reach, and a stance foot
  // it leaves out of reach lifts (clamp 6). (The pig in the 2 m frame, blocked at stairs.json's
  // top riser, set a forefoot down far ahead and was pulled 8 cm down onto the step's corner, a
  // rib 3.1 mm in it.) A need larger than the descent is a box the body was in already (a wall
  // it stands at), which this clamp does not climb; one larger than kTrunkSinkOfHip, or a
  // landing's descent, is a fall, which the legs take (random creature 28, landing 0.9 m down a
  // block of rough.json, held 0.3 m up off its feet, slid them 0.14 m).
  const bool sank = std::isnan(p.in.root) && trunk.raise > 0.0f && trunk.raise <= fell - std::max(raise, 0.0f) &&
                    trunk.raise <= kTrunkSinkOfHip * rig.hip_height;
  const float kept = sank ? trunk.raise : 0.0f;
  const float trunk_raise = std::max(std::min(trunk.raise, std::max(least_room - raise, 0.0f)), kept);
  p.body.root_y_ws += raise;
  // Whatever of the need the body does not rise by leaves a bone in the box (beyond the keep).
  auto left_in = [&](float risen) {
    if (p.trunk_left_in && trunk.raise - risen > kTrunkKeepOfHip * rig.hip_height + 1e-3f) *p.trunk_left_in = true;
  };
  left_in(trunk_raise);
  if (!(trunk_raise > 0.0f)) return;
  // The room was measured before this clamp (a rolling foot's reach moves with its joint): a
  // stance foot the trunk's raise still puts further out of reach than it was takes it back,
  // as far as needed (it would be released, and each foot released frees more room for the
  // next raise: a deer blocked at a ledge, its skull over the top, lifted off all four feet).
  thread_local std::vector<float> before;
  before.resize(rig.legs.size());
  GirdleJointFs joints;
  for (size_t i = 0; i < rig.legs.size(); ++i) before[i] = std::max(stance_excess(p, i, joints), 0.0f);
  auto worse = [&] {
    GirdleJointFs now;
    float most = 0.0f;
    for (size_t i = 0; i < rig.legs.size(); ++i) most = std::max(most, stance_excess(p, i, now) - before[i]);
    return most;
  };
  p.body.root_y_ws += trunk_raise;
  float back = 0.0f;
  for (int pass = 0; pass < 4; ++pass) {
    const float over = worse();
    if (!(over > 0.0f)) return;
    const float step = std::min(2.0f * over + kReachCheckSlack, trunk_raise - kept - back);
    if (!(step > 0.0f)) return;
    p.body.root_y_ws -= step;
    back += step;
    left_in(trunk_raise - back);
  }
  if (worse() > 0.0f) {
    p.body.root_y_ws -= trunk_raise - kept - back;
    left_in(kept);
  }
}

// 6. The raising clamps (2, 3, 5) may stretch a stance leg again past its reach (a girdle over
// a higher step lifts the body while another girdle's feet stand lower): such a foot lifts at
// the next chance instead of sliding (the gait clock reads the hand-off).
void release_overstretched_feet(Placement& p) {
  if (p.reach_checked && p.body.root_y_ws == p.checked_root && p.body.pitch == p.checked_pitch) return;
  GirdleJointFs joints;
  for (size_t i = 0; i < p.ctx.rig.legs.size(); ++i) {
    if (stance_excess(p, i, joints) > 0.0f) (*p.release)[p.feet.foot_of_leg[i]] = 1;
  }
}

}  // namespace ossa::anim::placement
