#include "ossa/anim/animator.h"

// The orchestrator: runs the stages of DESIGN.md §7 in order and keeps the state between
// ticks. Each stage's rules live in its own file (see animator.h).

#include <algorithm>
#include <cmath>

#include "ossa/anim/anim_math.h"
#include "ossa/anim/body_motion.h"
#include "ossa/anim/foothold.h"
#include "ossa/anim/leg_ik.h"
#include "ossa/anim/locomotion.h"
#include "ossa/anim/swing.h"
#include "ossa/anim/turn.h"
#include "ossa/assert.h"

namespace ossa {

using namespace anim;

namespace {

// Smoothing rates (1/s, × interpolation_speed_multiplier) of the lean, the walk→run blend,
// the gait blend, the pitch and the root height.
constexpr float kLeanRate = 6.0f, kRunRate = 5.0f, kGaitRate = 4.0f, kPitchRate = 10.0f, kRootRate = 14.0f;
// A blocked creature tests the way ahead again this often, seconds.
constexpr float kBlockedRetrySeconds = 0.5f;
// Below this (m/s, and of the stick) the creature stands.
constexpr float kStandingSpeed = 1e-4f;
// A reset looks for ground from this many hip heights (and at least 1 m) above the position.
constexpr float kResetSearchOfHip = 2.0f;
// The ground profile: columns a tenth of the shortest foot-or-leg size wide (at least 5 mm,
// at most 2 cm); its window reaches this many body lengths plus strides either side and
// this many hip heights above and below the root.
constexpr float kProfileStepOfFoot = 0.1f, kProfileSpanStrides = 2.0f;
// ...of strides at least this many hip heights long (a walk's: a creature setting off needs
// no wider window at once).
constexpr float kProfileStrideOfHip = 2.5f, kProfileAboveOfHip = 1.0f, kProfileBelowOfHip = 4.0f;

}  // namespace

Animator::Animator(const Creature& creature, SplinePrototypes prototypes, AnimatorParams params)
    : Animator(creature, build_anim_rig(creature), std::move(prototypes), params) {}

Animator::Animator(const Creature& creature, std::shared_ptr<const AnimRig> rig, SplinePrototypes prototypes, AnimatorParams params)
    : Animator(std::move(rig), std::move(prototypes), params) {
  creature_ = &creature;
  // Which of the creature's limbs each rig leg drives (the rig knows bones, not limbs).
  leg_limb_.assign(rig_->legs.size(), 0);
  for (size_t i = 0; i < rig_->legs.size(); ++i) {
    for (size_t l = 0; l < creature.limbs.size(); ++l) {
      if (creature.limbs[l].bones == rig_->legs[i].bones) leg_limb_[i] = static_cast<int>(l);
    }
  }
}

Animator::Animator(std::shared_ptr<const AnimRig> rig, SplinePrototypes prototypes, AnimatorParams params)
    : rig_(std::move(rig)), spline_prototypes_(std::move(prototypes)), params_(params) {
  OSSA_ASSERT(rig_ != nullptr, "Animator: no rig");
  const size_t legs = rig_->legs.size();
  pose_ = rig_->rest_pose;
  model_ = rig_->model_rest;
  feet_.feet.resize(legs);
  feet_.foot_of_leg.resize(legs);
  for (size_t i = 0; i < legs; ++i) {
    feet_.foot_of_leg[i] = static_cast<int>(i);
    feet_.feet[i].offset = leg_phase_offset(*rig_, static_cast<int>(i), 0.0f, 0.0f);
  }
  handoff_.lift_now.assign(legs, 0);
  leg_dirs_.resize(legs);
}

const Creature& Animator::creature() const {
  OSSA_ASSERT(creature_ != nullptr, "Animator::creature: this animator drives a rig without a Creature");
  return *creature_;
}

const Limb& Animator::leg_limb(int leg) const { return creature().limbs[leg_limb_[leg]]; }

// ---- Reset ----------------------------------------------------------------------------------

void Animator::reset(glm::vec2 position_ws, const Level& level, int facing) {
  const AnimRig& rig = *rig_;
  // A position inside a box (a spawn placed in the ground) stands on the ground above it.
  position_ws = level.free_point_above(position_ws);
  body_.facing = facing < 0 ? -1 : 1;
  body_.x_ws = position_ws.x;
  body_.lean = body_.pitch = 0.0f;
  speed_ = 0.0f;
  gait_.phase = gait_.frequency = 0.0f;
  gait_.moving = false;
  gait_.run_factor = gait_.trot_factor = gait_.gallop_factor = 0.0f;
  gait_.gait = rig.legs.empty() ? Gait::kCrawl : Gait::kIdle;
  block_.blocked = false;
  tail_ = {};
  body_state_.root_vy = body_state_.body_lift = 0.0f;
  steps_ = 0;
  idle_time_ = 0.0f;
  loco_ = {};
  level_revision_ = level.revision();
  const float search = std::max(kResetSearchOfHip * rig.hip_height, 1.0f);
  const float snap = std::max(kResetSnapOfHip * rig.hip_height, kResetSnapMin);
  auto ground_at = [&](float x0, float x1, float fallback) {
    auto hit = ground_below(level, std::min(x0, x1), std::max(x0, x1), position_ws.y + search, search + snap);
    return hit ? hit->height_ws : fallback;
  };
  // No ground within the snap below: the creature starts in the air, its feet where the
  // position is, and falls.
  const bool falling = !ground_below(level, rig.body_lo_ws(body_.x_ws, body_.facing), rig.body_hi_ws(body_.x_ws, body_.facing),
                                     position_ws.y + search, search + snap);
  body_.root_y_ws = ground_at(rig.body_lo_ws(body_.x_ws, body_.facing), rig.body_hi_ws(body_.x_ws, body_.facing), position_ws.y) + rig.root_rest_y;
  for (size_t i = 0; i < rig.legs.size(); ++i) {
    const RigLeg& info = rig.legs[i];
    const glm::vec2 ankle = bone_end(rig.model_rest[info.bones[1]], rig.skeleton.length(info.bones[1]));
    FootState& f = feet_.of_leg(static_cast<int>(i));
    f = FootState{};
    f.offset = leg_phase_offset(rig, static_cast<int>(i), gait_.trot_factor, gait_.gallop_factor);
    const float x = body_.to_ws(ankle + info.foot_offset_ms).x;
    f.pos_ws = {x, ground_at(x - 0.02f, x + 0.02f, position_ws.y)};
  }
  refresh_ground(level);
  const AnimContext ctx = context(level);
  const FootholdInputs in{ctx, body_, gait_.stride, gait_.duty, &feet_};
  // Each foot stands where it fits (not across the edge of a step).
  for (size_t i = 0; i < rig.legs.size(); ++i) {
    glm::vec2 landing;
    FootState& f = feet_.of_leg(static_cast<int>(i));
    if (!falling && find_landing(in, static_cast<int>(i), f.pos_ws, f.pos_ws.x, &landing)) f.pos_ws = landing;
    update_stance_clearance(ctx, f);
  }
  if (falling) {
    take_off(ctx, body_, {0.0f, 0.0f}, false, feet_, loco_);  // counts a fall
    for (FootState& f : feet_.feet) f.air_offset = glm::vec2(0.0f);
  } else {
    place_body(0.0f, false, level);
  }
  build_pose(0.0f, level);
}

void Animator::respawn(const Level& level) {
  const LocomotionStats stats = loco_.stats;
  reset(level.spawn_ws, level, body_.facing);
  const int falls = loco_.stats.falls;  // a spawn point in the air is a fall again
  loco_.stats = stats;
  loco_.stats.falls += falls;
  ++loco_.stats.respawns;
}

// ---- Update: the stages in order -------------------------------------------------------------

void Animator::refresh_ground(const Level& level) {
  // Stage 1: the profile covers the body, a reach and kProfileSpanStrides strides either side.
  const AnimRig& rig = *rig_;
  // The root need not be the middle of the body: a whole body length either side.
  const float reach = 2.0f * rig.body_half_length + rig.longest_contact_reach;
  const float span = reach + kProfileSpanStrides * std::max(gait_.stride, kProfileStrideOfHip * rig.hip_height);
  const float x0 = body_.x_ws - span, x1 = body_.x_ws + span;
  // Above the root: a hip height, or as high as the steepest slope rises over the body and a
  // leg's reach (a long, low body meets the hill ahead above its own height).
  const float above = std::max(kProfileAboveOfHip * rig.hip_height, GroundProfile::kMaxSlope * reach);
  const float lo = body_.root_y_ws - 0.75f * kProfileBelowOfHip * rig.hip_height;
  const float hi = body_.root_y_ws + 0.5f * above;
  if (ground_.covers(level, x0, x1, lo, hi)) return;
  float size = 1e30f;
  for (const RigLeg& leg : rig.legs) size = std::min(size, std::max(leg.foot_length, 0.25f * leg.reach));
  if (rig.legs.empty()) size = rig.hip_height;
  const float step = std::clamp(kProfileStepOfFoot * size, 0.005f, 0.02f);
  // Twice the window, so that it lasts for a while.
  ground_.build(level, x0 - span, x1 + span, body_.root_y_ws + above, above + kProfileBelowOfHip * rig.hip_height, step);
}

void Animator::block(int leg) {
  block_.blocked = true;
  if (leg >= 0) block_.leg = leg;
  block_.dir = body_.facing;
  block_.retry = kBlockedRetrySeconds;
}

bool Animator::way_ahead_open(const Level& level, float speed) {
  // Re-tested now and then while blocked: the level may have changed.
  const AnimContext ctx = context(level);
  const FootholdInputs in{ctx, body_, gait_.stride, gait_.duty, &feet_};
  glm::vec2 landing;
  return find_landing(in, block_.leg, step_from(feet_.of_leg(block_.leg)), landing_x(in, block_.leg, speed), &landing);
}

void Animator::update(float dt, const AnimatorIntent& intent, const Level& level) {
  const float desired_velocity = intent.velocity;
  if (!(dt > 0.0f) || !std::isfinite(desired_velocity)) return;
  const AnimRig& rig = *rig_;
  const float ism = std::max(params_.interpolation_speed_multiplier, 0.01f);
  if (dt != decay_.dt || ism != decay_.ism) {
    decay_ = {dt, ism, std::exp(-kLeanRate * ism * dt), std::exp(-kRunRate * ism * dt), std::exp(-kGaitRate * ism * dt),
              std::exp(-kPitchRate * ism * dt), std::exp(-kRootRate * ism * dt)};
  }
  refresh_ground(level);                                                      // 1 ground profile
  const AnimContext ctx = context(level);
  if (level.revision() != level_revision_) {  // the level changed: a foot whose ground went hangs
    level_revision_ = level.revision();
    for (size_t i = 0; i < rig.legs.size(); ++i) {
      FootState& f = feet_.of_leg(static_cast<int>(i));
      if (f.state == LegState::kStance && !ground_below(level, f.pos_ws.x - 1e-3f, f.pos_ws.x + 1e-3f, f.pos_ws.y + 1e-3f, 2e-3f)) {
        hang(ctx, body_, static_cast<int>(i), 1.0f, f);
      }
    }
  }
  if (loco_.mode == Locomotion::kAirborne) {                                  // 3 locomotion: in the air
    fly(dt, level);
    build_pose(dt, level);
    return;
  }
  const bool landing = loco_.mode == Locomotion::kLanding;
  if (landing) loco_.time += dt;
  if (intent.jump && loco_.mode == Locomotion::kGrounded && !rig.legs.empty()) begin_crouch(rig, params_, loco_);
  const int want = desired_velocity > kStandingSpeed ? 1 : desired_velocity < -kStandingSpeed ? -1 : 0;
  const bool turned = !landing && want != 0 && want != body_.facing;
  if (turned) turn_round(ctx, spline_prototypes_, gait_.run_factor, gait_.stride, gait_.duty, body_, feet_);

  float target = std::fabs(desired_velocity);
  if (block_.blocked) {
    if (want != block_.dir) {
      block_.blocked = false;
    } else {
      target = 0.0f;
      block_.retry -= dt;
      if (block_.retry <= 0.0f && !rig.legs.empty()) {
        block_.retry = kBlockedRetrySeconds;
        if (way_ahead_open(level, std::fabs(desired_velocity))) block_.blocked = false;
      }
    }
  }
  // The stick sets the speed precisely [T 4.1]; starting and stopping are immediate [T 5.1]
  // (the half-length first step and the eased stop make them read well). A landing's
  // descent holds the body still.
  speed_ = target <= kStandingSpeed || landing ? 0.0f : target;
  update_gait(rig, params_, speed_, decay_.run, decay_.gait, gait_);         // 2 gait clock
  body_.lean = approach(body_.lean, -params_.max_spine_rotation * std::min(speed_ / run_speed(), 1.2f), decay_.lean);

  float dx = body_.facing * speed_ * dt;                                      // body motion
  const BodyMotionResult swept = sweep_body(ctx, body_, model_, dx, body_boxes_);
  if (swept.hit_wall) block(-1);
  dx = limit_by_legs(ctx, body_, feet_, swept.dx, handoff_);
  const float ledge = limit_by_ledges(ctx, body_, feet_, gait_.stride, dx);  // a face it cannot climb
  if (ledge == 0.0f && dx != 0.0f) block(-1);
  dx = ledge;
  body_.x_ws += dx;

  if (rig.legs.empty()) {
    crawl_phase_ = frac(crawl_phase_ + speed_ * dt / std::max(rig.body_half_length, 0.05f));
    if (block_.blocked) speed_ = 0.0f;
    gait_.gait = speed_ > 0.0f ? Gait::kCrawl : Gait::kIdle;
    idle_time_ += dt;
  } else {
    step_legs(dt, ism, level);                                                // 4 foothold, 5 swing
    if (block_.blocked) speed_ = 0.0f;
    advance_swings(dt, level);
    update_air_feet(ctx, body_, 1.0f, dt, true, feet_);  // feet reaching down over a drop, or to land
  }
  const bool take_off_now = loco_.mode == Locomotion::kCrouch && advance_crouch(rig, params_, dt, loco_);
  place_body(dt, turned, level);                                              // 6 body placement
  // 3 locomotion: take-off at the crouch's end (forwards at the speed asked for, even from a
  // standstill at a step), stepping off the last foothold, or the end of a landing.
  if (take_off_now) {
    take_off(ctx, body_, {body_.facing * std::max(speed_, std::fabs(desired_velocity)), jump_speed(rig, params_)}, true, feet_, loco_);
    block_.blocked = false;
  } else if (!landing && (rig.legs.empty() ? legless_over_drop(ctx, body_) : unsupported(feet_))) {
    take_off(ctx, body_, {body_.facing * speed_, 0.0f}, false, feet_, loco_);
  } else if (landing && std::isnan(landing_root(loco_))) {
    end_landing(level);
  }
  if (below_kill_height(level)) respawn(level);  // came down on a floor at the kill height
  build_pose(dt, level);                                                      // 7 IK, 8 limbs, 9 FK
}

bool Animator::below_kill_height(const Level& level) const {
  // Where the feet would stand under the root: a creature standing on a floor at the kill
  // height is below it once its legs give on landing. The default margin scales with the
  // creature (Level::kill_y).
  return body_.root_y_ws - rig_->root_rest_y < level.kill_y(rig_->hip_height);
}

void Animator::fly(float dt, const Level& level) {
  const AnimContext ctx = context(level);
  const bool touched = airborne_tick(ctx, dt, decay_.pitch, model_, body_boxes_, body_, feet_, loco_);
  speed_ = std::fabs(loco_.vx);
  body_state_.root_vy = loco_.vy;
  if (below_kill_height(level)) {
    respawn(level);
  } else if (touched) {
    begin_landing(ctx, body_, standing_root(ctx, placement_inputs(dt, false), feet_, body_), loco_);
    gait_.moving = false;
    place_body(dt, false, level);  // the clamps at once: no knee or girdle in the ground on touch-down
  }
}

void Animator::end_landing(const Level& level) {
  // Feet that found no ground as the body came down set down where they can.
  loco_.mode = Locomotion::kGrounded;
  const AnimContext ctx = context(level);
  const FootholdInputs in{ctx, body_, gait_.stride, gait_.duty, &feet_};
  for (size_t i = 0; i < rig_->legs.size(); ++i) {
    FootState& f = feet_.of_leg(static_cast<int>(i));
    if (!f.air) continue;
    f.air = false;
    f.hang_beyond = NAN;
    f.from_ws = f.pos_ws;
    start_ease(in, static_cast<int>(i), f);
  }
}

void Animator::step_legs(float dt, float ism, const Level& level) {
  // The gait clock's lift-offs while moving (each plans its step); the eased set-down of
  // swinging feet after a stop.
  const AnimRig& rig = *rig_;
  const AnimContext ctx = context(level);
  const FootholdInputs in{ctx, body_, gait_.stride, gait_.duty, &feet_};
  const float dphi = gait_.frequency * dt;
  if (!(speed_ > 0.0f && !block_.blocked)) {
    gait_.moving = false;
    idle_time_ += dt;
    for (size_t i = 0; i < rig.legs.size(); ++i) {
      FootState& f = feet_.of_leg(static_cast<int>(i));
      if (f.air) continue;
      if (f.state == LegState::kSwing && !f.easing) start_ease(in, static_cast<int>(i), f);
      // A foot the body placement stretched past its reach steps to where it reaches, once,
      // rather than hang off its leg (and stays if there is no such place).
      if (f.state == LegState::kStance && handoff_.lift_now[feet_.foot_of_leg[i]]) restep_in_reach(in, static_cast<int>(i), f);
    }
    return;
  }
  const bool starting = !gait_.moving;
  if (starting) start_clock(gait_, feet_, 0);  // the lead leg lifts now; its first step is half a stride
  gait_.phase = frac(gait_.phase + dphi);
  update_target_offsets(rig, gait_);
  for (size_t i = 0; i < rig.legs.size(); ++i) {
    const int leg = static_cast<int>(i);
    FootState& f = feet_.of_leg(leg);
    const LegPhase lp = advance_leg_phase(gait_, f, gait_.target_offset[i], starting, ism, dt);
    if (f.air) {
      // hanging over a drop (locomotion.h)
    } else if (f.state == LegState::kStance) {
      bool lift = lp.lift_due || handoff_.lift_now[feet_.foot_of_leg[i]];
      // A foot left behind (a gait change, a shortened step) lifts before it would slide.
      const RigLeg& info = rig.legs[i];
      const glm::vec2 joint = lift ? glm::vec2(0.0f) : body_.to_fs(body_.girdle_ws(rig, info.girdle));
      const glm::vec2 contact = body_.to_fs(f.pos_ws);
      if (!lift && contact.x - info.foot_span < joint.x) {  // else its anchor is ahead of the joint
        float r;
        const glm::vec2 anchor = leg_anchor(ctx, body_, leg, contact, joint, f.stance_clear, &r);
        if (glm::length(anchor - joint) > kFootReach * r && anchor.x < joint.x) lift = true;
      }
      const float swing_phase = std::max(1.0f - lp.phase, 0.05f);
      if (lift && !set_new_splines(in, spline_prototypes_, gait_.run_factor, speed_, leg, f, swing_phase)) {
        // No foothold ahead: over a drop deeper than the legs reach the foot steps off and
        // reaches down past the edge; a wall too tall (or the way walled off) stops the creature.
        float beyond;
        if (drop_ahead(in, leg, f.pos_ws, landing_x(in, leg, speed_, swing_phase), &beyond)) {
          f.floor = f.pos_ws.y - kFloorBelowLedge;  // a fall that follows lands lower than this ledge
          hang(ctx, body_, leg, 1.0f, f);
          f.hang_beyond = beyond;
        } else {
          block(leg);
        }
      }
    } else if (!f.easing) {
      f.progress += f.rate * dphi;
    }
    f.phase_prev = lp.phase;
  }
}

void Animator::advance_swings(float dt, const Level& level) {
  const AnimContext ctx = context(level);
  const FootholdInputs in{ctx, body_, gait_.stride, gait_.duty, &feet_};
  const SwingTick tick{dt, speed_, gait_.moving};
  for (size_t i = 0; i < rig_->legs.size(); ++i) {
    FootState& f = feet_.of_leg(static_cast<int>(i));
    if (f.state == LegState::kSwing && !f.air && advance_swing(in, tick, static_cast<int>(i), f)) ++steps_;
  }
}

PlacementInputs Animator::placement_inputs(float dt, bool turned) const {
  PlacementInputs in;
  in.dt = dt;
  in.speed = speed_;
  in.bob = body_bob(*rig_, params_, spline_prototypes_, gait_, idle_time_);
  in.snap = turned;
  in.turning = turned;
  in.keep_pitch = decay_.pitch;
  in.keep_root = decay_.root;
  in.crouch = loco_.mode == Locomotion::kCrouch ? loco_.crouch : 0.0f;
  in.root = landing_root(loco_);
  return in;
}

void Animator::place_body(float dt, bool turned, const Level& level) {
  anim::place_body(context(level), placement_inputs(dt, turned), feet_, body_, body_state_, handoff_);
}

}  // namespace ossa
