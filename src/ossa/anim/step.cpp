#include "ossa/anim/step.h"

// [SECTION] transitions of one foot
// [SECTION] reset and the level's changes
// [SECTION] lift-offs and swings
// [SECTION] leaving the ground, the air, landing

#include <algorithm>
#include <cmath>

#include "ossa/anim/anim_math.h"
#include "ossa/anim/animator_params.h"
#include "ossa/anim/leg_geometry.h"
#include "ossa/anim/locomotion.h"
#include "ossa/anim/swing.h"

namespace ossa::anim {

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
// A jump's feet leave the ground once their legs are this many times their standing length.
constexpr float kPushOffOfStanding = 1.15f;
// A foot touching down after waiting for the body hangs instead if its leg is out of reach by
// more than this fraction of the leg's contact reach and another foot of its girdle stands
// higher than this one by more than kHangStraddleOfReach of it.
constexpr float kHangOverreachOfReach = 0.05f, kHangStraddleOfReach = 0.5f;
// A falling foot reaches for a ledge ahead (ledge_ahead) whose top lies at least this many of
// its leg's reach below the girdle joint; onto it this many foot lengths past the edge, from
// this many of its leg's reach above the top.
constexpr float kLedgeBelowJointOfReach = 0.3f, kLedgeMarginOfFoot = 0.25f, kLedgeLiftOfReach = 0.05f;

}  // namespace

// [SECTION] transitions of one foot -------------------------------------------------------------

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
  f.tucked = false;
  f.from_ws = f.to_ws = f.pos_ws;
  f.swing_clear = Clearance{};  // knows nothing: the leg IK tests the hanging leg against the level
}

void plant(const AnimContext& ctx, FootState& f, glm::vec2 p) {
  f.state = LegState::kStance;
  ++f.plantings;
  f.air = false;
  f.pos_ws = f.from_ws = f.to_ws = p;
  f.progress = 0.0f;
  f.easing = false;
  f.hover = 0.0f;
  f.hang_beyond = NAN;
  f.tucked = false;
  note_ledge(ctx, f, f.floor < 1e29f ? f.floor + ctx.rig.scale.ledge_gap : NAN);
  f.floor = 1e30f;
  update_stance_clearance(ctx, f);
}

void unhang(FootState& f) {
  f.air = false;
  f.hang_beyond = NAN;
  f.tucked = false;
  f.from_ws = f.to_ws = f.pos_ws;
}

bool foot_consistent(const FootState& f) {
  if (f.air && (f.state != LegState::kSwing || f.easing || f.hover != 0.0f)) return false;
  if ((!std::isnan(f.hang_beyond) || f.tucked) && !f.air) return false;
  return !(f.easing && f.state != LegState::kSwing);
}

// [SECTION] reset and the level's changes ---------------------------------------------------------

void reset_feet(const AnimContext& ctx, const BodyFrame& body, const GaitState& gait, float ground_y_fallback,
                float search_from_y, float search_depth, bool falling, StepState& step) {
  const AnimRig& rig = ctx.rig;
  step.steps = 0;
  step.level_revision = ctx.level.revision();
  for (size_t i = 0; i < rig.legs.size(); ++i) {
    const RigLeg& info = rig.legs[i];
    const glm::vec2 ankle = bone_end(rig.model_rest[info.bones[1]], rig.skeleton.length(info.bones[1]));
    FootState& f = step.feet.of_leg(static_cast<int>(i));
    f = FootState{};
    const float x = body.to_ws(ankle + info.foot_offset_ms).x;
    auto hit = ground_below(ctx.level, x - rig.scale.ground_span, x + rig.scale.ground_span, search_from_y, search_depth);
    f.pos_ws = {x, hit ? hit->height_ws : ground_y_fallback};
  }
  // Each foot stands where it fits (not across the edge of a step).
  const FootholdInputs in = planner(ctx, body, gait, step.feet);
  for (size_t i = 0; i < rig.legs.size(); ++i) {
    glm::vec2 landing;
    FootState& f = step.feet.of_leg(static_cast<int>(i));
    if (!falling && find_landing(in, static_cast<int>(i), f.pos_ws, f.pos_ws.x, &landing)) f.pos_ws = landing;
    update_stance_clearance(ctx, f);
  }
}

void watch_level(const AnimContext& ctx, const BodyFrame& body, StepState& step) {
  const Level& level = ctx.level;
  if (level.revision() == step.level_revision) return;
  step.level_revision = level.revision();
  for (size_t i = 0; i < ctx.rig.legs.size(); ++i) {
    FootState& f = step.feet.of_leg(static_cast<int>(i));
    // A standing foot whose ground went hangs.
    if (f.state == LegState::kStance && !ground_below(level, f.pos_ws.x - 1e-3f, f.pos_ws.x + 1e-3f, f.pos_ws.y + 1e-3f, 2e-3f)) {
      hang(ctx, body, static_cast<int>(i), 1.0f, f);
    }
    // The clearance caches describe the old level: worked out again (a hanging foot's knows
    // nothing, as it should).
    if (f.state == LegState::kStance) {
      update_stance_clearance(ctx, f);
    } else if (!f.air) {
      update_swing_clearance(ctx, static_cast<int>(i), f);
    }
  }
}

// [SECTION] lift-offs and swings -------------------------------------------------------------------

namespace {

// Should stance leg `leg`, whose lift-off is not due, lift now? It was asked to (the body motion
// or the body placement), or it is left behind (a gait change, a shortened step) and would slide.
bool lift_now(const AnimContext& ctx, const BodyFrame& body, int leg, const FootState& f, bool asked) {
  if (asked) return true;
  const RigLeg& info = ctx.rig.legs[leg];
  const glm::vec2 joint = body.to_fs(body.girdle_ws(ctx.rig, info.girdle));
  const glm::vec2 contact = body.to_fs(f.pos_ws);
  if (!(contact.x - info.foot_span < joint.x)) return false;  // its anchor is ahead of the joint
  float r;
  const glm::vec2 anchor = leg_anchor(ctx, body, leg, contact, joint, f.stance_clear, &r);
  return glm::length(anchor - joint) > kFootReach * r && anchor.x < joint.x;
}

}  // namespace

void step_feet(const AnimContext& ctx, const SplinePrototypes& prototypes, const BodyFrame& body, const GaitState& gait,
               float speed, float dt, TickHandoff& handoff, StepState& step) {
  const AnimRig& rig = ctx.rig;
  FootSet& feet = step.feet;
  const FootholdInputs in = planner(ctx, body, gait, feet);
  auto asked = [&](int leg) {
    const int k = feet.foot_of_leg[leg];
    return handoff.lift_now[k] == kLiftNow || handoff.release_next[k];
  };
  if (!gait.moving) {
    // Standing: swinging feet set down, eased; a foot the body placement stretched past its
    // reach steps to where it reaches, once, rather than hang off its leg (and stays if there
    // is no such place).
    for (size_t i = 0; i < rig.legs.size(); ++i) {
      const int leg = static_cast<int>(i);
      FootState& f = feet.of_leg(leg);
      if (f.air) continue;
      if (f.state == LegState::kSwing && !f.easing) start_ease(in, leg, f);
      if (f.state == LegState::kStance && asked(leg)) restep_in_reach(in, leg, f);
    }
    return;
  }
  const float dphi = gait.frequency * dt;  // cycles the clock advanced
  for (size_t i = 0; i < rig.legs.size(); ++i) {
    const int leg = static_cast<int>(i);
    FootState& f = feet.of_leg(leg);
    const LegPhase& lp = handoff.leg_phase[i];
    if (f.air) continue;  // hanging over a drop (update_air_feet)
    if (f.state == LegState::kSwing) {
      if (!f.easing) f.progress += f.rate * dphi;
      continue;
    }
    const bool optional = handoff.lift_now[feet.foot_of_leg[i]] == kLiftIfPlaced;
    if (!lp.lift_due && !lift_now(ctx, body, leg, f, asked(leg) || optional)) continue;
    const float swing_phase = std::max(1.0f - lp.phase, 0.05f);
    if (set_new_splines(in, prototypes, gait.run_factor, speed, leg, f, swing_phase)) continue;
    // (A foot that lifts only for its flesh, finding no foothold, stands.)
    if (optional && !lp.lift_due && !lift_now(ctx, body, leg, f, asked(leg))) continue;
    // No foothold ahead: over a drop deeper than the legs reach the foot steps off and reaches
    // down past the edge; a wall too tall (or the way walled off) stops the creature.
    float beyond;
    if (drop_ahead(in, leg, f.pos_ws, landing_x(in, leg, speed, swing_phase), &beyond)) {
      f.floor = f.pos_ws.y - ctx.rig.scale.ledge_gap;  // a fall that follows lands lower than this ledge
      hang(ctx, body, leg, 1.0f, f);
      f.hang_beyond = beyond;
    } else {
      handoff.no_foothold_leg = leg;
    }
  }
}

void lift_overstretched_feet(const AnimContext& ctx, const SplinePrototypes& prototypes, const BodyFrame& body,
                             const GaitState& gait, float speed, const TickHandoff& handoff, StepState& step) {
  FootSet& feet = step.feet;
  const FootholdInputs in = planner(ctx, body, gait, feet);
  for (size_t i = 0; i < ctx.rig.legs.size(); ++i) {
    const int leg = static_cast<int>(i);
    FootState& f = feet.of_leg(leg);
    if (!handoff.release_next[feet.foot_of_leg[i]] || f.air || f.state != LegState::kStance) continue;
    if (handoff.turned) continue;  // the turn's tick: the feet were just handed over (stage 4)
    // Out of its leg's reach where the body now stands?
    if (!(leg_overreach(ctx, body, leg, f, body.to_fs(body.girdle_ws(ctx.rig, ctx.rig.legs[i].girdle))) > 0.0f)) continue;
    if (!gait.moving) {
      restep_in_reach(in, leg, f);
      continue;
    }
    // No foothold for a step: it hangs (reaching down for ground, update_air_feet) rather than
    // stay planted out of reach.
    if (!set_new_splines(in, prototypes, gait.run_factor, speed, leg, f, std::max(1.0f - handoff.leg_phase[i].phase, 0.05f))) {
      hang(ctx, body, leg, 1.0f, f);
    }
  }
}

void advance_feet(const AnimContext& ctx, const BodyFrame& body, const GaitState& gait, float speed, float dt,
                  TickHandoff& handoff, StepState& step) {
  FootSet& feet = step.feet;
  const FootholdInputs in = planner(ctx, body, gait, feet);
  const SwingTick swing{dt, speed, gait.moving};
  for (size_t i = 0; i < ctx.rig.legs.size(); ++i) {
    FootState& f = feet.of_leg(static_cast<int>(i));
    if (f.state != LegState::kSwing || f.air) continue;
    const bool waited = f.hover >= kMaxHoverSeconds;
    if (!advance_swing(in, swing, static_cast<int>(i), f)) continue;
    if (!waited) {
      ++step.steps;
      continue;
    }
    // A foot that waited in vain for the body to come down to its landing, with no place
    // below its joint in reach, hangs and reaches down for ground rather than stand out of its
    // leg's reach, where another foot of its girdle stands higher than the leg straddles (a
    // ledge between them: body placement would pull the girdle down past that foot to this
    // one; a hind foot left below a ledge the body walks back up dropped the body 0.4 m in a
    // tick, its forelegs' knees into the ledge's top). Otherwise it sets down and the girdle
    // comes down to it.
    const int leg = static_cast<int>(i);
    const int girdle = ctx.rig.legs[i].girdle;
    const float straddle = kHangStraddleOfReach * ctx.rig.legs[i].contact_reach;
    const bool held_up = std::any_of(ctx.rig.girdles[girdle].legs.begin(), ctx.rig.girdles[girdle].legs.end(), [&](int other) {
      const FootState& o = feet.of_leg(other);
      return other != leg && o.state == LegState::kStance && !o.air && o.pos_ws.y - f.pos_ws.y > straddle;
    });
    if (held_up &&
        leg_overreach(ctx, body, leg, f, body.to_fs(body.girdle_ws(ctx.rig, girdle))) >
            kHangOverreachOfReach * ctx.rig.legs[i].contact_reach) {
      --f.plantings;  // (advance_swing counted the touch-down it hangs from instead)
      hang(ctx, body, leg, 1.0f, f);
      continue;
    }
    ++step.steps;
  }
  update_air_feet(ctx, body, 1.0f, dt, true, feet);  // feet reaching down over a drop, or to land
  for (size_t k = 0; k < feet.feet.size(); ++k) {
    const FootState& f = feet.feet[k];
    handoff.waiting[k] = f.state == LegState::kSwing && f.hover > 0.0f;
  }
}

// [SECTION] leaving the ground, the air, landing ---------------------------------------------------

namespace {
// Would leg `leg` reach a contact at p_ws as a stance leg (body placement's clamp 1: the contact,
// or the ankle where the level holds the foot, within kFootReach of its radius)?
bool stance_reaches(const AnimContext& ctx, const BodyFrame& body, int leg, glm::vec2 p_ws) {
  float r;
  const glm::vec2 joint_fs = body.to_fs(body.girdle_ws(ctx.rig, ctx.rig.legs[leg].girdle));
  const glm::vec2 anchor = leg_anchor(ctx, body, leg, body.to_fs(p_ws), joint_fs, Clearance{}, &r);
  return glm::length(anchor - joint_fs) <= kFootReach * r;
}

// Falling, a foot with no ground below it within its leg's reach (or only ground more than a
// step below the ledge), short of a ledge ahead whose top lies below its girdle and no higher
// than the foot, its edge within the leg's reach ahead of the joint: where on that top it
// reaches for (the nearest such ledge; *over: the foot is
// over its top already). A jump that falls short of the far side of a gap
// lands its feet on the edge, rather than the body coming down into the ledge's top.
bool ledge_ahead(const AnimContext& ctx, const BodyFrame& body, int leg, const FootState& f, glm::vec2* onto, bool* over) {
  const RigLeg& info = ctx.rig.legs[leg];
  const glm::vec2 joint = body.girdle_ws(ctx.rig, info.girdle);
  const float R = kFootReach * info.contact_reach, facing = static_cast<float>(body.facing);
  const FootSpan span = foot_span_ws(info, body.facing);
  // Ground below within its reach: only a ledge more than a step above that ground (a
  // sinornis leaping onto a rough.json block 6 cm up, its feet hanging behind the riser, came
  // down with its belly on the top and its thigh across the block's corner).
  float lowest = joint.y - R;
  if (auto below = ground_below(ctx.level, f.pos_ws.x + span.lo, f.pos_ws.x + span.hi, f.pos_ws.y + 1e-3f, R)) {
    lowest = std::max(lowest, below->height_ws + ctx.params.max_step_up * ctx.rig.climb_height);
  }
  const float highest = std::min(joint.y - kLedgeBelowJointOfReach * R, f.pos_ws.y);
  if (!(highest > lowest)) return false;
  const float far = joint.x + facing * R;
  ctx.hits.clear();
  ctx.level.overlapping(Box{{std::min(f.pos_ws.x, far), lowest}, {std::max(f.pos_ws.x, far), highest}}, ctx.hits);
  float best = 1e30f;
  for (int h : ctx.hits) {
    const Box& c = ctx.level.box(h);
    const float top = c.max_ws.y, face = facing > 0.0f ? c.min_ws.x : c.max_ws.x;
    if (top < lowest || top > highest) continue;
    // The whole foot on the top, a little past its edge.
    const float x = face - (facing > 0.0f ? span.lo : span.hi) + facing * kLedgeMarginOfFoot * info.foot_length;
    const float ahead = facing * (face - (f.pos_ws.x + (facing > 0.0f ? span.lo : span.hi)));
    if (facing * (x - joint.x) > R || ahead > best) continue;
    auto hit = ground_below(ctx.level, x + span.lo, x + span.hi, f.pos_ws.y + 1e-3f, f.pos_ws.y + 1e-3f - lowest);
    if (!hit || std::fabs(hit->height_ws - top) > 1e-3f) continue;  // another box stands on it there
    best = ahead;
    *onto = {x, top};
    *over = ahead <= 0.0f;
  }
  return best < 1e29f;
}
}  // namespace

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
    glm::vec2 onto(0.0f);
    bool over = false;
    if (may_land && !reach_ground && ledge_ahead(ctx, body, leg, f, &onto, &over)) {
      // Over the ledge's top the foot comes down onto it (and is planted there below); short of
      // it, it goes over its edge a little above it. From where it is, at the rate the air
      // offset eases.
      const float lift = kLedgeLiftOfReach * info.contact_reach;
      next = f.pos_ws + (onto + glm::vec2(0.0f, over ? -lift : lift) - f.pos_ws) * (1.0f - keep);
      f.air_offset = next - target;
    }
    if (reach_ground) {
      // On the ground (stepping off, landing) a hanging foot reaches down to ground its leg
      // reaches below it, so a drop within the legs' reach is stepped down, not fallen.
      const glm::vec2 j = body.girdle_ws(ctx.rig, info.girdle);
      const float r = kFootReach * info.contact_reach, dx = next.x - j.x;
      if (std::fabs(dx) < r) {
        const float lowest = j.y - reach_across(r, dx);
        auto hit = ground_below(ctx.level, next.x + span.lo, next.x + span.hi, std::min(f.pos_ws.y, f.floor), f.pos_ws.y - lowest);
        // Only ground the leg reaches as a stance leg would (body placement's clamp 1: the
        // contact, or the ankle where the level holds the foot): a foot planted beyond that
        // pulled the body down after it in one tick.
        if (hit && !stance_reaches(ctx, body, leg, {next.x, hit->height_ws})) hit.reset();
        if (hit && hit->height_ws < next.y) {
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
        if ((hit->height_ws < f.floor || across) && may_land && stance_reaches(ctx, body, leg, {next.x, hit->height_ws})) {
          // A foot come down beside a riser with its toe or heel already in it (random 11's hind
          // toe, 6.3 mm, after a jump on rough.json) sets down where the whole foot fits.
          glm::vec2 at(next.x, hit->height_ws), spot;
          const FootholdInputs fit{ctx, body};
          if (!foot_fits(fit, leg, at) && nearest_fit(fit, leg, at, &spot, true) && stance_reaches(ctx, body, leg, spot)) at = spot;
          plant(ctx, f, at);
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
    // Nor its drawn flesh about shin and foot (RigLeg::flesh_margin): the lines from the joint
    // to either side of the foot by that margin stop short of a box too (a foreleg hanging
    // past the far wall of drops.json's gap laid its flesh 4 cm across the wall's corner).
    if (const float r = std::max(info.flesh_margin[1], info.flesh_margin[2]); r > 0.0f && next != joint) {
      const glm::vec2 d = next - joint, side = glm::vec2(-d.y, d.x) * (r / glm::length(d));
      float t = 1.0f;
      for (const glm::vec2 s : {side, -side}) {
        if (auto hit = ctx.level.raycast(joint, next + s); hit && hit->t < t) t = hit->t;
      }
      if (t < 1.0f) next = joint + d * std::max(t - 0.02f, 0.0f);
    }
    f.pos_ws = f.from_ws = f.to_ws = next;
  }
  return planted;
}

void leave_ground(const AnimContext& ctx, const BodyFrame& body, bool jump, float floor, bool from_rest, StepState& step) {
  const AnimRig& rig = ctx.rig;
  const int n = static_cast<int>(rig.girdles.size());
  for (size_t i = 0; i < rig.legs.size(); ++i) {
    FootState& f = step.feet.of_leg(static_cast<int>(i));
    f.floor = floor;
    if (f.air) continue;
    // A jump's feet on the ground push off until their legs are stretched (push_off_and_reach);
    // a quadruped's front feet leave first, so the hind legs push last.
    const bool front = n > 1 && rig.legs[i].girdle == 0;
    if (jump && f.state == LegState::kStance && !front) continue;
    hang(ctx, body, static_cast<int>(i), 0.0f, f);
  }
  // Placed in the air (a reset): the feet hang right where they are.
  if (from_rest) {
    for (FootState& f : step.feet.feet) f.air_offset = glm::vec2(0.0f);
  }
}

void push_off_and_reach(const AnimContext& ctx, const BodyFrame& body, float vy, float extension, float dt, TickHandoff& handoff,
                        StepState& step) {
  const AnimRig& rig = ctx.rig;
  // Feet still on the ground push off until their legs are stretched past their standing
  // length (a bird's crouched legs reach much further than they stand: they leave the ground
  // long before they are straight), or the reach, and none stays once the body comes down.
  for (size_t i = 0; i < rig.legs.size(); ++i) {
    const int leg = static_cast<int>(i);
    FootState& f = step.feet.of_leg(leg);
    if (f.state != LegState::kStance) continue;
    const glm::vec2 joint = body.to_fs(body.girdle_ws(rig, rig.legs[i].girdle));
    float r;
    const glm::vec2 anchor = leg_anchor(ctx, body, leg, body.to_fs(f.pos_ws), joint, f.stance_clear, &r);
    const float standing = kPushOffOfStanding * rig.girdles[rig.legs[i].girdle].rest_height * ctx.params.stance_height;
    if (glm::length(anchor - joint) > std::min(r, standing) || vy <= 0.0f) hang(ctx, body, leg, 0.0f, f);
  }
  // (Rising, a foot that pushed off is carried along the ground, not planted again.)
  handoff.planted = update_air_feet(ctx, body, extension, dt, false, step.feet, vy < 0.0f);
}

void set_down_after_landing(const AnimContext& ctx, const BodyFrame& body, const GaitState& gait, StepState& step) {
  const FootholdInputs in = planner(ctx, body, gait, step.feet);
  for (size_t i = 0; i < ctx.rig.legs.size(); ++i) {
    FootState& f = step.feet.of_leg(static_cast<int>(i));
    if (!f.air) continue;
    // A foot with no ground to step to hangs on (a hind foot in drops.json's gap, the forefeet
    // on the far ledge: set down where it hung, it stood on nothing, and the horse stood blocked
    // over the gap); it reaches for the ground as the body moves on (update_air_feet).
    glm::vec2 landing;
    if (!find_landing(in, static_cast<int>(i), f.pos_ws, f.pos_ws.x, &landing)) continue;
    unhang(f);
    start_ease(in, static_cast<int>(i), f);
  }
}

}  // namespace ossa::anim
