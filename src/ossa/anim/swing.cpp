#include "ossa/anim/swing.h"

#include <algorithm>
#include <cmath>

#include "ossa/anim/anim_math.h"
#include "ossa/anim/animator_params.h"
#include "ossa/anim/leg_geometry.h"

namespace ossa::anim {

namespace {

// A path that would have to rise more than this many leg-plus-foot lengths meets a wall.
constexpr float kMaxRaiseOfLeg = 2.0f;
constexpr int kRaiseIterations = 8;
// Below this bump (near lift-off and touch-down) a needed raise counts as at this bump.
constexpr float kMinBump = 0.1f;
// A foot the body placement stretched past its reach steps to a spot within this fraction of
// the reach (restep_in_reach).
constexpr float kRestepReachUse = 0.9f;
// A foot about to land where its leg's drawn outline would cut a step looks for a spot where
// it does not within this many of the leg's lengths of its landing (a shift, not a new step).
constexpr float kFleshSpotOfLeg = 0.25f;
// ... and no further out of its leg's reach than this fraction of the reach.
constexpr float kFleshSpotReachSlack = 0.02f;

}  // namespace

SwingShape step_shape(const SplinePrototypes& prototypes, float run_factor, float lift, float rate, bool easing) {
  return {prototypes[PrototypeId::kLegSwingX].blended(run_factor), prototypes[PrototypeId::kLegSwingY].blended(run_factor),
          lift, rate, easing};
}

SwingShape ease_shape(float ease_time) {
  return {HermiteSpline({{0.0f, 0.0f, 1.0f}, {1.0f, 1.0f, 1.0f}}), HermiteSpline({{0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}), 0.0f,
          1.0f / std::max(ease_time, 0.01f), true};
}

namespace {

// swing_point's height alone (a check of the path's heights needs no x). Inline in both: once
// per swinging foot and tick, and a dozen times per step planned.
[[gnu::always_inline]] inline float swing_height(const FootState& f, float s) {
  const float up = f.to_ws.y - f.from_ws.y;
  const float ease = up >= 0.0f ? smoothstep(0.0f, 0.55f, s) : smoothstep(0.45f, 1.0f, s);
  const float lift = prototype_range(PrototypeId::kLegSwingY).clamp(f.swing_y.position(s));
  return f.from_ws.y + ease * up + f.lift * lift + (f.raise != 0.0f ? f.raise * bump(s) : 0.0f);
}

// swing_point, inline in this file's callers (the swing of every foot, every tick).
[[gnu::always_inline]] inline glm::vec2 point_on_swing(const FootState& f, float s) {
  // The blended prototype shapes the step [T 4.4.1]; on steps the foot rises before it moves
  // forward (up) or moves over before it descends (down), so it never clips a riser's corner.
  const float up = f.to_ws.y - f.from_ws.y;
  const float sx = up > 0.0f ? std::clamp((s - 0.12f) / 0.88f, 0.0f, 1.0f)
                 : up < 0.0f ? std::clamp(s / 0.85f, 0.0f, 1.0f) : s;
  const float along = prototype_range(PrototypeId::kLegSwingX).clamp(f.swing_x.position(sx));
  return {f.from_ws.x + along * (f.to_ws.x - f.from_ws.x), swing_height(f, s)};
}

}  // namespace

glm::vec2 swing_point(const FootState& f, float s) { return point_on_swing(f, s); }

void update_stance_clearance(const AnimContext& ctx, FootState& f) {
  // Any leg's foot may stand here after a turn: the longest foot's circle around the contact,
  // and as far as any leg reaches from it (the steps between a foot and its girdle).
  const float r = ctx.rig.longest_foot_reach;
  f.stance_clear = clearance_in(Box{f.pos_ws - glm::vec2(r), f.pos_ws + glm::vec2(r)}, f.pos_ws.y, ctx.level, ctx.hits);
  const float reach = ctx.rig.longest_contact_reach;
  f.stance_reach_clear =
      clearance_in(Box{f.pos_ws - glm::vec2(reach, 0.0f), f.pos_ws + glm::vec2(reach)}, f.pos_ws.y, ctx.level, ctx.hits);
}

void update_swing_clearance(const AnimContext& ctx, int leg, FootState& f) {
  // Everything the leg may sweep through on this swing: around the path, a leg's length
  // to either side and two above.
  const RigLeg& info = ctx.rig.legs[leg];
  const float reach = info.reach + info.foot_span;
  const glm::vec2 lo = glm::min(f.from_ws, f.to_ws), hi = glm::max(f.from_ws, f.to_ws);
  f.swing_clear =
      clearance_in(Box{lo - glm::vec2(1.5f * reach, reach), hi + glm::vec2(1.5f * reach, 2.0f * reach)}, lo.y, ctx.level, ctx.hits);
}

bool raise_for_clearance(const AnimContext& ctx, int facing, int leg, FootState& f) {
  const RigLeg& info = ctx.rig.legs[leg];
  const glm::vec2 ankle_rel = info.ankle_rel_ms;
  const glm::vec2 tip_rel = info.tip_rel_ms;
  // What rises near the path (kept: the leg IK tests the swinging leg against it too). When
  // nothing rises above its lower end (flat ground, or down a slope), a coarse check that the
  // curve stays above that suffices.
  update_swing_clearance(ctx, leg, f);
  if (f.swing_clear.top < f.swing_clear.base) {
    const float lowest = std::min(f.from_ws.y, f.to_ws.y) - std::min(0.0f, ankle_rel.y);
    bool above = true;
    for (int k = 1; k < 12 && above; ++k) above = swing_height(f, static_cast<float>(k) / 12.0f) >= lowest;
    if (above) return true;
  }
  Box foot[kSwingSamples], flesh[kSwingSamples];
  // A foot that stands pressed against a step (turned round on a narrow tread) only has to
  // clear it once it has left it.
  auto foot_box = [&](float s) {
    const glm::vec2 p = point_on_swing(f, s);
    const glm::vec2 q = p + glm::vec2(facing * ankle_rel.x, ankle_rel.y);
    const glm::vec2 r = p + glm::vec2(facing * tip_rel.x, tip_rel.y);
    // A little narrower than find_landing's test, so a landing it found clears at its end
    // (rig_scale.h).
    const RigScale& scale = ctx.rig.scale;
    return Box{glm::min(glm::min(p, q), r) - glm::vec2(scale.swing_side, 0.0f),
               glm::max(glm::max(p, q), r) + glm::vec2(scale.swing_side, scale.swing_top)};
  };
  // The same with the foot's flesh (foothold.h flesh_span_ws). A box the flesh meets where the
  // foot lifts or lands (find_landing found none whose flesh clears: treads narrower than the
  // foot and its flesh) is cleared by the bones alone.
  const FootSpan bones_span = foot_span_ws(info, facing), flesh_span = flesh_span_ws(info, facing);
  const bool has_flesh = flesh_span.lo != bones_span.lo || flesh_span.hi != bones_span.hi;
  const glm::vec2 flesh_lo(bones_span.lo - flesh_span.lo, 0.0f), flesh_hi(flesh_span.hi - bones_span.hi, 0.0f);
  auto fleshed = [&](const Box& b) { return Box{b.min_ws - flesh_lo, b.max_ws + flesh_hi}; };
  foot[0] = foot_box(0.0f);
  flesh[0] = fleshed(foot[0]);
  const Box flesh_end = fleshed(foot_box(1.0f));
  std::vector<int>& hits = ctx.hits;
  for (int iter = 0; iter < kRaiseIterations; ++iter) {
    // The foot's box at each sample, then the colliders near the whole path in one query.
    Box path{glm::vec2(1e30f), glm::vec2(-1e30f)};
    for (int k = 1; k < kSwingSamples; ++k) {
      foot[k] = foot_box(static_cast<float>(k) / kSwingSamples);
      flesh[k] = fleshed(foot[k]);
      path.min_ws = glm::min(path.min_ws, flesh[k].min_ws);
      path.max_ws = glm::max(path.max_ws, flesh[k].max_ws);
    }
    hits.clear();
    ctx.level.overlapping(path, hits);
    float need = 0.0f;
    for (int h : hits) {
      const Box& box = ctx.level.box(h);
      const Box* boxes = has_flesh && !box.overlaps(flesh[0]) && !box.overlaps(flesh_end) ? flesh : foot;
      int k = 1;
      if (box.overlaps(boxes[0])) {
        while (k < kSwingSamples && box.overlaps(boxes[k])) ++k;
      }
      for (; k < kSwingSamples; ++k) {
        if (!box.overlaps(boxes[k])) continue;
        const float depth = box.top() + ctx.rig.scale.swing_clearance - boxes[k].min_ws.y;
        need = std::max(need, depth / std::max(bump(static_cast<float>(k) / kSwingSamples), kMinBump));
      }
    }
    if (need <= 0.0f) return true;
    f.raise += need;
    if (f.raise > kMaxRaiseOfLeg * (info.reach + info.foot_span)) break;  // a wall, not a step
  }
  return false;
}

bool begin_swing(const AnimContext& ctx, const BodyFrame& body, int leg, FootState& f, glm::vec2 to_ws, const SwingShape& shape) {
  f.state = LegState::kSwing;
  f.from_ws = f.pos_ws;
  f.to_ws = to_ws;
  f.swing_x = shape.swing_x;
  f.swing_y = shape.swing_y;
  f.lift = shape.lift;
  f.raise = 0.0f;
  f.progress = 0.0f;
  f.rate = shape.rate;
  f.easing = shape.easing;
  return raise_for_clearance(ctx, body.facing, leg, f);
}

bool set_new_splines(const FootholdInputs& in, const SplinePrototypes& prototypes, float run_factor, float speed, int leg,
                     FootState& f, float swing_phase) {
  glm::vec2 landing;
  if (!find_landing(in, leg, f.pos_ws, landing_x(in, leg, speed, swing_phase), &landing)) return false;
  const float reach = in.ctx.rig.legs[leg].reach;
  if (!begin_swing(in.ctx, in.body, leg, f, landing, step_shape(prototypes, run_factor, reach, 1.0f / std::max(swing_phase, 0.05f), false))) {
    f.state = LegState::kStance;
    f.to_ws = f.from_ws;
    return false;
  }
  return true;
}

void start_ease(const FootholdInputs& in, int leg, FootState& f, const glm::vec2* to) {
  glm::vec2 landing;
  if (to) {
    landing = *to;
  } else if (!find_landing(in, leg, step_from(f), f.pos_ws.x, &landing)) {
    landing = f.to_ws;
  }
  // Set down where the leg reaches from where the body stopped: drawn in towards the joint.
  if (!to && !reaches(in, leg, landing)) {
    const RigLeg& info = in.ctx.rig.legs[leg];
    const glm::vec2 joint = in.body.to_fs(in.body.girdle_ws(in.ctx.rig, info.girdle));
    const float reach = kFootReach * info.contact_reach;
    const float h = joint.y - landing.y;
    const float reach_x = 0.9f * reach_across(reach, h);
    const float dx = std::clamp(in.body.to_fs(landing).x - joint.x, -reach_x, reach_x);
    // On the landing's ground, else on the ground the girdle stands over (a foot left far
    // behind on a step the body has left), else the nearest fit at all.
    const float under = in.body.girdle_ws(in.ctx.rig, info.girdle).y -
                        in.ctx.rig.girdles[info.girdle].rest_height * in.ctx.params.stance_height;
    glm::vec2 spot, under_spot;
    const bool fits = nearest_fit(in, leg, in.body.to_ws({joint.x + dx, landing.y}), &spot, true);
    if (fits && !reaches(in, leg, spot) && nearest_fit(in, leg, in.body.to_ws({joint.x + dx, under}), &under_spot, true) &&
        reaches(in, leg, under_spot)) {
      landing = under_spot;
    } else if (fits) {
      landing = spot;
    }
  }
  begin_swing(in.ctx, in.body, leg, f, landing, ease_shape(in.ctx.params.stop_ease_time));
}

bool restep_in_reach(const FootholdInputs& in, int leg, FootState& f) {
  const RigLeg& info = in.ctx.rig.legs[leg];
  const glm::vec2 joint = in.body.girdle_ws(in.ctx.rig, info.girdle);
  glm::vec2 spot;
  // Well within reach of the joint where it is now (a spot at the limit of the reach is where
  // the foot came from: the body placement could not keep it), looked for from the ground the
  // girdle stands over (a foot stretched down into a dip finds the ground beside it).
  const float ground = std::max(f.pos_ws.y, joint.y - in.ctx.rig.girdles[info.girdle].rest_height * in.ctx.params.stance_height);
  if (!nearest_fit(in, leg, {joint.x, ground}, &spot, true, kRestepReachUse) || !reaches(in, leg, spot, kRestepReachUse) ||
      glm::length(spot - f.pos_ws) < 1e-3f) {
    return false;
  }
  start_ease(in, leg, f, &spot);
  return true;
}

void step_to(const FootholdInputs& in, int leg, FootState& f, glm::vec2 spot) {
  start_ease(in, leg, f, &spot);
  // Already lifted on this tick: the first sample of a path cleared from the second on.
  f.progress = 1.0f / static_cast<float>(kSwingSamples);
  f.pos_ws = point_on_swing(f, f.progress);
}

namespace {

// A step re-aims when its landing is more than this fraction of the stride beyond the wanted
// one, until this much of the swing is done.
constexpr float kReaimOfStride = 0.08f;
constexpr float kReaimUntil = 0.9f;

// A foot standing at contact_ws, with what is near it as its clearance (update_stance_clearance).
FootState standing_at(const AnimContext& ctx, glm::vec2 contact_ws) {
  FootState standing;
  standing.pos_ws = standing.from_ws = standing.to_ws = contact_ws;
  update_stance_clearance(ctx, standing);
  return standing;
}

// Does the leg standing at `standing` cut the level (stance_leg_hits, the flesh too) with its
// girdle joint at joint_fs, or, the foot ahead of the joint, once the body has carried the
// joint over it? (There as high over the ground as now where the ground is known: a body
// carried up a step rises with it.)
bool stance_cuts(const AnimContext& ctx, const BodyFrame& body, int leg, const FootState& standing, glm::vec2 joint_fs) {
  if (stance_leg_hits(ctx, body, leg, standing, joint_fs, true)) return true;
  const glm::vec2 contact = body.to_fs(standing.pos_ws);
  if (!(contact.x > joint_fs.x)) return false;
  const glm::vec2 joint_ws = body.to_ws(joint_fs);
  const float under = ctx.ground.spans(joint_ws.x, joint_ws.x) ? ctx.ground.highest(joint_ws.x, joint_ws.x, joint_ws.y) : NAN;
  const float rise = std::isnan(under) ? 0.0f : std::max(standing.pos_ws.y - under, 0.0f);
  return stance_leg_hits(ctx, body, leg, standing, glm::vec2(contact.x, joint_fs.y + rise), true);
}

// The nearest spot to near_ws within kFleshSpotOfLeg of the leg's length, as high (on the same
// tread: shifted up a step, the eared seal's hind flipper stood at the riser above and never
// lifted again), where the foot fits with its flesh and the leg standing there, its girdle joint
// at joint_fs, cuts nothing (stance_leg_hits, the flesh too) and reaches the foot, or nearly
// (leg_overreach within kFleshSpotReachSlack of the reach: the body placement lowers the body
// that little; a forefoot stepping down stairs finds room for its leg ahead, where the body is
// about to come down to).
bool nearest_clear_stance(const FootholdInputs& in, int leg, glm::vec2 near_ws, glm::vec2 joint_fs, glm::vec2* spot) {
  const AnimRig& rig = in.ctx.rig;
  const RigLeg& info = rig.legs[leg];
  const float up = in.ctx.params.max_step_up * rig.climb_height;
  const float step = rig.scale.search_step;
  const int n = std::max(1, static_cast<int>(kFleshSpotOfLeg * info.reach / step));
  const float sole = rig.flat_contact ? in.body.facing * info.foot_length : 0.0f;
  const float sole_lo = std::min(sole, 0.0f) - rig.scale.sole_side, sole_hi = std::max(sole, 0.0f) + rig.scale.sole_side;
  const float allowed = kFleshSpotReachSlack * info.contact_reach;
  for (int k = 1; k <= 2 * n; ++k) {
    const float x = near_ws.x + step * static_cast<float>(k % 2 == 0 ? k / 2 : -(k + 1) / 2);
    const auto hit = ground_below(in.ctx.level, x + sole_lo, x + sole_hi, near_ws.y + up, 2.0f * up);
    if (!hit || std::fabs(hit->height_ws - near_ws.y) > 1e-3f) continue;  // on the same tread
    const glm::vec2 p(x, hit->height_ws);
    if (!foot_fits(in, leg, p, true)) continue;  // (the flesh's span holds the bones')
    const FootState standing = standing_at(in.ctx, p);
    if (leg_overreach(in.ctx, in.body, leg, standing, joint_fs) > allowed) continue;
    if (stance_cuts(in.ctx, in.body, leg, standing, joint_fs)) continue;
    *spot = p;
    return true;
  }
  return false;
}

}  // namespace

bool advance_swing(const FootholdInputs& in, const SwingTick& tick, int leg, FootState& f) {
  const AnimContext& ctx = in.ctx;
  const BodyFrame& body = in.body;
  const int facing = body.facing;
  if (f.easing) f.progress += f.rate * tick.dt;
  if (!f.easing && f.progress < kReaimUntil && tick.moving) {
    const float remaining = (1.0f - f.progress) / std::max(f.rate, 1e-3f);
    const float wanted = landing_x(in, leg, tick.speed, remaining);
    if (facing * (f.to_ws.x - wanted) > kReaimOfStride * in.stride) {
      glm::vec2 landing;
      if (find_landing(in, leg, step_from(f), wanted, &landing) && facing * (landing.x - f.to_ws.x) < 0.0f) {
        const glm::vec2 old_to = f.to_ws;
        const float old_raise = f.raise;
        f.to_ws = landing;
        if (!raise_for_clearance(ctx, facing, leg, f)) {  // keep the old landing
          f.to_ws = old_to;
          f.raise = old_raise;
          update_swing_clearance(ctx, leg, f);
        }
      }
    }
  }
  if (f.progress >= 1.0f && !foot_fits(in, leg, f.to_ws)) {
    // Planned facing the other way (the creature turned meanwhile): the foot would reach into
    // a step. It moves on to the nearest place it fits.
    glm::vec2 spot;
    if (nearest_fit(in, leg, f.to_ws, &spot, true) && glm::length(spot - f.to_ws) > 1e-4f) {
      step_to(in, leg, f, spot);
      return false;
    }
  }
  if (f.progress >= 1.0f && !f.easing) {
    // A trailing foot about to land where its leg, standing, would cut a box (the lip of a
    // ledge its body has stepped down from meanwhile) sets down on the nearest place below
    // its joint that it reaches instead.
    // (Only down a ledge deeper than a step down: on stairs the step stage keeps such legs.)
    const RigGirdle& girdle = ctx.rig.girdles[ctx.rig.legs[leg].girdle];
    const glm::vec2 joint_ws = body.girdle_ws(ctx.rig, ctx.rig.legs[leg].girdle);
    const glm::vec2 joint_fs = body.to_fs(joint_ws);
    const auto under = ground_below(ctx.level, joint_ws.x - 1e-3f, joint_ws.x + 1e-3f, joint_ws.y, 2.0f * girdle.rest_height);
    const bool ledge = under && f.to_ws.y - under->height_ws > ctx.params.max_step_down * girdle.rest_height;
    if (ledge && body.to_fs(f.to_ws).x < joint_fs.x) {
      FootState standing;
      standing.pos_ws = standing.from_ws = standing.to_ws = f.to_ws;
      glm::vec2 spot;
      if (stance_leg_hits(ctx, body, leg, standing, joint_fs) &&
          nearest_fit(in, leg, body.to_ws({joint_fs.x, f.to_ws.y}), &spot) && reaches(in, leg, spot) &&
          glm::length(spot - f.to_ws) > 1e-3f) {
        start_ease(in, leg, f, &spot);
        return false;
      }
    }
  }
  if (f.progress >= 1.0f && !f.easing && tick.moving) {
    // A foot stepping down further than the leg reaches from the still-high body waits above
    // its landing point while the body comes down to it (body placement lowers the girdle).
    const RigLeg& info = ctx.rig.legs[leg];
    const glm::vec2 joint = body.to_fs(body.girdle_ws(ctx.rig, info.girdle));
    float r;
    const glm::vec2 anchor = leg_anchor(ctx, body, leg, body.to_fs(f.to_ws), joint, f.swing_clear, &r);
    if (glm::length(anchor - joint) > r) {
      if (f.hover < kMaxHoverSeconds && std::fabs(anchor.x - joint.x) < r) {
        f.hover += tick.dt;
        f.progress = 1.0f;
        f.pos_ws = f.to_ws;
        return false;
      }
      // The body did not come down in time (other feet hold it up), or the landing lies beyond
      // the leg's reach across (the body moved on: set down there, the girdle would drop to it
      // in a tick): set the foot down on the nearest place below the joint it reaches instead,
      // from where it hangs now.
      glm::vec2 spot;
      const glm::vec2 below_joint = body.to_ws({joint.x, f.to_ws.y});
      if (nearest_fit(in, leg, below_joint, &spot) && reaches(in, leg, spot)) {
        const float R = info.contact_reach;
        const float dxj = body.to_fs(f.to_ws).x - joint.x;
        f.pos_ws = body.to_ws({body.to_fs(f.to_ws).x, joint.y - reach_across(R, dxj)});
        start_ease(in, leg, f, &spot);
        f.hover = 0.0f;
        return false;
      }
    }
  }
  if (f.progress >= 1.0f && !f.easing && !ctx.rig.legs[leg].flesh_outline.empty()) {
    // A foot about to land where its leg's drawn outline, standing, would cut a step (a hind
    // foot set down at a riser's foot, its leg slanting up to the hip ahead through the riser;
    // a forefoot stepping down, its leg slanting back over the corner of the step above) sets
    // down on the nearest spot close by where it does not, if there is one.
    const glm::vec2 joint_fs = body.to_fs(body.girdle_ws(ctx.rig, ctx.rig.legs[leg].girdle));
    // (Not a foot landing out of its leg's reach: it is released and steps again, and a spot
    // found for it was too: an ichthyornis in a rough.json slot stepped between two for good.)
    const FootState landing = standing_at(ctx, f.to_ws);
    glm::vec2 spot;
    if (stance_cuts(ctx, body, leg, landing, joint_fs) && !(leg_overreach(ctx, body, leg, landing, joint_fs) > 0.0f) &&
        nearest_clear_stance(in, leg, f.to_ws, joint_fs, &spot)) {
      // At the swing's own pace (a stride in the swing's time), no slower than a stop's ease:
      // a tick or two for a few centimetres. (Eased for as long as a stop, a running pigeon's
      // shifted foot came down after its body had climbed on, its shin in a stair's corner.)
      const float shift = glm::length(spot - f.to_ws);
      const float pace = tick.moving ? tick.speed / std::max(1.0f - in.duty, 0.1f) : 0.0f;
      const float most = ctx.params.stop_ease_time;
      begin_swing(ctx, body, leg, f, spot, ease_shape(pace > 0.0f ? std::min(shift / pace, most) : most));
      return false;
    }
  }
  if (f.progress >= 1.0f) {
    f.hover = 0.0f;
    f.state = LegState::kStance;
    ++f.plantings;
    f.pos_ws = f.to_ws;
    f.easing = false;
    note_ledge(ctx, f);
    update_stance_clearance(ctx, f);
    return true;
  }
  f.pos_ws = point_on_swing(f, std::clamp(f.progress, 0.0f, 1.0f));
  return false;
}

}  // namespace ossa::anim
