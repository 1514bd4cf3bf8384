#include "ossa/anim/animator.h"

// The orchestrator: runs the stages of DESIGN.md §7 in the order of the stage list in
// Animator::update, and keeps the state between ticks (animator.h lists each piece with its
// owning stage). Every rule lives in its stage's file; here are only the calls, in order.

#include <algorithm>
#include <cstdio>
#include <cmath>

#include "ossa/anim/anim_math.h"
#include "ossa/anim/level_probe.h"
#include "ossa/anim/secondary_motion.h"
#include "ossa/anim/trunk_bob.h"
#include "ossa/anim/turn.h"
#include "ossa/assert.h"

namespace ossa {

using namespace anim;

namespace {

// Smoothing rates (1/s, × interpolation_speed_multiplier) of the lean, the walk→run blend,
// the gait blend, the pitch and the root height.
constexpr float kLeanRate = 6.0f, kRunRate = 5.0f, kGaitRate = 4.0f, kPitchRate = 10.0f, kRootRate = 14.0f;
// The girdles' bob is smoothed only against jumps (a start, a stop, a turn): its cut-off lies
// above a trot's twice-per-stride bounce.
constexpr float kBobRate = 40.0f;
// A reset looks for ground from this many hip heights (and at least 1 m) above the position.
constexpr float kResetSearchOfHip = 2.0f;
// A reset places the body clear of walls by this share of its half length.
constexpr float kResetClearOfHalfLength = 0.05f;
// The most a standing body goes back out of a step in one tick, of the hip height.
constexpr float kStandingPushOfHip = 0.03f;
// The most it goes back in one tick for its stance legs' drawn outline to leave a step ahead,
// of the hip height (a pigeon blocked at a riser, its knee 2 cm in it: 11 %).
constexpr float kStanceFleshPushOfHip = 0.15f;

// Does a bone of the trunk (AnimRig::trunk, the skull's left out) lie in a wall
// (kMaxTrunkRaiseOfHip)?
bool trunk_in_wall(const AnimContext& ctx, const BodyFrame& body) {
  const AnimRig& rig = ctx.rig;
  for (size_t i = 0; i < rig.trunk_level_from; ++i) {
    const glm::vec2 a = body.body_point_ws(rig, rig.trunk[i].a), b = body.body_point_ws(rig, rig.trunk[i].b);
    if (raise_to_clear(a, b, ctx.level, ctx.hits) >= kMaxTrunkRaiseOfHip * rig.hip_height) return true;
  }
  return false;
}

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
  init_pose(*rig_, pose_);
  step_.feet.feet.resize(legs);
  step_.feet.foot_of_leg.resize(legs);
  for (size_t i = 0; i < legs; ++i) step_.feet.foot_of_leg[i] = static_cast<int>(i);
  reset_offsets(*rig_, anim::gait_family(*rig_, params_), step_.feet, gait_);
  handoff_.resize(legs);
}

const Creature& Animator::creature() const {
  OSSA_ASSERT(creature_ != nullptr, "Animator: this animator drives a rig without a Creature");
  return *creature_;
}

const Limb& Animator::leg_limb(int leg) const { return creature().limbs[leg_limb_[leg]]; }

Animator::BlockReport Animator::block_report() const {
  BlockReport r;
  r.blocked = motion_.block.blocked || motion_.block.trial > 0.0f;
  r.climb_m = params_.max_step_up * rig_->climb_height;
  r.step_down_m = params_.max_step_down * rig_->hip_height;
  r.jump_m = jump_rise(*rig_, params_);
  if (!r.blocked || ground_.size() == 0) return r;
  // Its feet: the leading girdle's lowest standing foot (those that must climb: the hind feet
  // may still stand a step lower), else any standing one, else where its hip height puts them.
  float feet = INFINITY, any = INFINITY;
  for (size_t leg = 0; leg < rig_->legs.size(); ++leg) {
    const anim::FootState& f = step_.feet.of_leg(static_cast<int>(leg));
    if (f.state != LegState::kStance || f.air) continue;
    any = std::min(any, f.pos_ws.y);
    if (rig_->legs[leg].girdle == 0) feet = std::min(feet, f.pos_ws.y);  // (girdles: front first)
  }
  if (!std::isfinite(feet)) feet = any;
  if (!std::isfinite(feet)) feet = body_.root_y_ws - rig_->hip_height;
  // The ground ahead: from the root to a body length past its front (a stopped creature's
  // stride says nothing of how far its next step would go).
  const int dir = motion_.block.dir != 0 ? motion_.block.dir : body_.facing;
  const float front = dir > 0 ? rig_->body_hi_ws(body_.x_ws, dir) : rig_->body_lo_ws(body_.x_ws, dir);
  const float a = body_.x_ws, b = front + dir * std::max(gait_.stride, rig_->scale.length);
  const int i0 = ground_.column_of(std::min(a, b)), i1 = ground_.column_of(std::max(a, b));
  // The profile holds the heights of its window only (a few hip heights about the root): a
  // column with none may hold ground above it, a step or a wall (the frog, on default.json's
  // first step after jumping onto it, read the next riser, 15 cm up, as a gap). Asked of the
  // level, up to twice its jump or four hip heights above its feet.
  const float look_up = feet + std::max(2.0f * r.jump_m, 4.0f * rig_->hip_height);
  for (int i = i0; i <= i1; ++i) {
    float h = ground_.column(i);
    if (std::isnan(h) && ground_.level() != nullptr && look_up > ground_.top()) {
      const float x = ground_.x0() + static_cast<float>(i) * ground_.step();
      if (auto above = anim::ground_below(*ground_.level(), x, x + ground_.step(), look_up, look_up - ground_.top())) h = above->height_ws;
    }
    if (std::isnan(h)) {
      r.drop_m = INFINITY;
      continue;
    }
    r.rise_m = std::max(r.rise_m, h - feet);
    r.drop_m = std::max(r.drop_m, feet - h);
  }
  return r;
}

std::string describe_block(const Animator::BlockReport& r) {
  if (!r.blocked) return {};
  char text[200];
  if (r.rise_m > r.climb_m) {
    std::snprintf(text, sizeof text, "blocked: a step %.2f m high ahead, its legs climb %.2f m; %s %.2f m",
                  static_cast<double>(r.rise_m), static_cast<double>(r.climb_m),
                  r.jump_m >= r.rise_m ? "jump: a jump rises" : "too high to jump: a jump rises",
                  static_cast<double>(r.jump_m));
  } else if (r.drop_m > r.step_down_m) {
    if (std::isinf(r.drop_m)) {
      std::snprintf(text, sizeof text, "blocked: a gap ahead with no ground its legs reach");
    } else {
      std::snprintf(text, sizeof text, "blocked: a drop of %.2f m ahead, its legs step down %.2f m",
                    static_cast<double>(r.drop_m), static_cast<double>(r.step_down_m));
    }
  } else {
    std::snprintf(text, sizeof text, "blocked: a wall or a foothold out of its reach ahead");
  }
  return text;
}

glm::vec2 Animator::foot_ws(int leg) const {
  const int b = rig_->legs[leg].contact_bone;
  return body_.to_ws(bone_end(pose_.facing[b], rig_->skeleton.length(b)));
}

// ---- Reset ----------------------------------------------------------------------------------

void Animator::reset(glm::vec2 position_ws, const Level& level, int facing) {
  const AnimRig& rig = *rig_;
  // A position inside a box (a spawn placed in the ground) stands on the ground above it.
  position_ws = level.free_point_above(position_ws);
  // A legless body lies along the ground of its whole length (a whale over a flight of stairs):
  // it looks for ground up to half its length above the position, and its crawl climb, not
  // the search, tells the ground from a wall (standing_ground).
  const float search = std::max({kResetSearchOfHip * rig.hip_height, 1.0f, rig.legs.empty() ? rig.body_half_length : 0.0f});
  const float snap = std::max(kResetSnapOfHip * rig.hip_height, kResetSnapMin);
  const float from = position_ws.y + search, depth = search + snap;
  // The body over the ground below the whole of it; no ground within the snap below: the
  // creature starts in the air, its feet where the position is, and falls. A body that would
  // stand in a wall (a whale's length behind a spawn point a metre from the level's end)
  // starts clear of it, as near the position as it fits; a legless body lies on no ground
  // higher than it crawls onto (a whale's tail beside an end wall lower than the search).
  const int dir = facing < 0 ? -1 : 1;
  const float reach = 4.0f * rig.body_half_length + 1.0f;
  // A body on legs stands on ground its legs climb onto: a wall higher than a step beside its
  // tail is a wall, not ground (the triceratops at default.json's spawn, 2 m from the 4 m end
  // wall, read the wall's top as ground under its tail and was not moved: it stood with its
  // tail on the top and its thigh's flesh 33 cm in the face).
  const float climb = rig.legs.empty() ? rig.crawl_climb : params_.max_step_up * rig.climb_height;
  // (Clear by a margin: a body draped along the ground reaches a little further than at rest,
  // and a tail touching the wall's face would lift the body over the wall.)
  const float margin = kResetClearOfHalfLength * rig.body_half_length;
  position_ws.x = clear_standing_x(level, position_ws.x, rig.body_lo_ws(0.0f, dir) - margin, rig.body_hi_ws(0.0f, dir) + margin,
                                   rig.body_top, from, depth, climb, reach, hits_);
  const auto ground = standing_ground(level, position_ws.x, rig.body_lo_ws(position_ws.x, dir), rig.body_hi_ws(position_ws.x, dir),
                                      from, depth, climb);
  const bool falling = !ground;
  reset_body(position_ws.x, (ground ? *ground : position_ws.y) + rig.root_rest_y, dir, body_, body_state_);
  motion_ = {};
  gait_.phase = gait_.frequency = 0.0f;
  gait_.moving = false;
  gait_.run_factor = gait_.mid_factor = gait_.fast_factor = 0.0f;
  gait_.gait = rig.legs.empty() ? Gait::kCrawl : Gait::kIdle;
  gait_.idle_time = 0.0f;
  gait_.walk_speed = walk_speed();
  pose_.tail = {};
  loco_ = {};
  handoff_.begin_tick();
  refresh_ground_profile(level, rig, body_, gait_.stride, ground_);
  const AnimContext ctx = context(level);
  reset_feet(ctx, body_, gait_, position_ws.y, from, depth, falling, step_);
  reset_offsets(rig, anim::gait_family(rig, params_), step_.feet, gait_);
  if (falling) {
    take_off(ctx, body_, {0.0f, 0.0f}, false, step_.feet, loco_);  // counts a fall
    leave_ground(ctx, body_, false, loco_.floor, true, step_);
  } else {
    place_body(ctx, 0.0f);
  }
  finish_tick(ctx, 0.0f);
}

void Animator::respawn(const Level& level) {
  const LocomotionStats stats = loco_.stats;
  reset(level.spawn_ws, level, body_.facing);
  const int falls = loco_.stats.falls;  // a spawn point in the air is a fall again
  loco_.stats = stats;
  loco_.stats.falls += falls;
  ++loco_.stats.respawns;
}

// ---- Update: the stage list -----------------------------------------------------------------

void Animator::update(float dt, const AnimatorIntent& intent, const Level& level) {
  if (!(dt > 0.0f) || !std::isfinite(intent.velocity)) return;
  // A small creature moves fast for its size: its gait cycles fast (the 3 cm frog hops 17
  // times a second, 7 ticks of 120 Hz a hop: a tick that long a part of the cycle left it 4 %
  // short of the commanded speed), and a fall covers much of its height in a tick (a 21 cm
  // hip falling 3 m, 6 cm a tick, touched down with its pelvis 6 cm in the ground). The tick
  // splits into substeps: at least kSubstepsPerCycle a gait cycle (16: the speed within 0.6 %
  // for every example), and no more than kFallStepOfHip hip heights of fall a substep. At
  // 120 Hz only the frog and the armored shrew take substeps walking on flat ground.
  const float cycles = gait_.frequency * dt * static_cast<float>(kSubstepsPerCycle);
  const float fall = std::fabs(vertical_speed()) * dt / (kFallStepOfHip * rig_->hip_height);
  const int n = std::clamp(static_cast<int>(std::ceil(std::max(cycles, fall))), 1, kMaxSubsteps);
  for (int i = 0; i < n; ++i) tick(dt / static_cast<float>(n), i == 0 ? intent : AnimatorIntent{intent.velocity, false}, level);
}

void Animator::tick(float dt, const AnimatorIntent& intent, const Level& level) {
  const AnimRig& rig = *rig_;
  const float ism = std::max(params_.interpolation_speed_multiplier, 0.01f);
  if (dt != decay_.dt || ism != decay_.ism) {
    decay_ = {dt, ism, std::exp(-kLeanRate * ism * dt), std::exp(-kRunRate * ism * dt), std::exp(-kGaitRate * ism * dt),
              std::exp(-kPitchRate * ism * dt), std::exp(-kRootRate * ism * dt), std::exp(-kBobRate * ism * dt)};
  }
  handoff_.begin_tick();
  refresh_ground_profile(level, rig, body_, gait_.stride, ground_);             //  1 ground profile
  const AnimContext ctx = context(level);
  watch_level(ctx, body_, step_);                                               //  2 step: the level changed

  if (loco_.mode == Locomotion::kAirborne) {
    float dx;                                                                   // A1 locomotion: the path
    if (fly_along(ctx, dt, body_, pose_.facing, body_boxes_, loco_, &dx)) move_body(dx, body_);
    const float y = path_height(ctx, body_, pose_.facing, body_boxes_, loco_);
    fly_body(y, loco_.vy, decay_.pitch, body_, body_state_);                    // A2 body placement
    push_off_and_reach(ctx, body_, loco_.vy, reach_extension(ctx, body_, loco_), dt, handoff_, step_);  // A3 step
    float floor;                                                                // A4 touch-down
    const bool touched = handoff_.planted > 0 || (body_may_land(loco_, step_.feet, &floor) && rest_body_on_ground(ctx, floor, body_));
    follow_path(loco_.vx, motion_);
    if (below_kill_height(rig, body_, level)) {                                 // A5 locomotion
      respawn(level);
    } else if (touched) {
      begin_landing(ctx, body_, standing_root(ctx, placement_inputs(dt), step_.feet, handoff_, body_), loco_);
      stop_clock(gait_);
      place_body(ctx, dt);  // the clamps at once: no knee or girdle in the ground on touch-down
    }
    finish_tick(ctx, dt);                                                       // 12 pose
    // A part of the body come down into a ledge ahead: the body goes back out of it.
    if (loco_.vy < 0.0f && go_back_from_face(ctx, 1e30f, true)) loco_.vx = 0.0f;
    return;
  }

  const bool landing = loco_.mode == Locomotion::kLanding;
  begin_tick(rig, params_, intent.jump, dt, loco_);                             //  3 locomotion: the crouch
  handoff_.turned = turn_wanted(intent.velocity, body_.facing, landing);
  if (handoff_.turned) {                                                        //  4 turn
    const float was_x = body_.x_ws;
    mirror_body(rig, pose_.facing, body_);
    // A turn that swings the trunk round into a wall ahead (random creature 10 of the hour's
    // set, a biped blocked with its back to a riser, turned its chest and ribs 1.1 cm into the
    // riser's top, more than the trunk clamp lifts) takes the body along the ground only as far
    // as the wall sweep lets it.
    const float shift = body_.x_ws - was_x;
    if (shift * static_cast<float>(body_.facing) > 0.0f && trunk_in_wall(ctx, body_)) {
      body_.x_ws = was_x;
      move_body(sweep_body(ctx, body_, pose_.facing, shift, body_boxes_).dx, body_);
    }
    turn_feet(ctx, spline_prototypes_, gait_, body_, step_.feet);
  }
  command_speed(planner(ctx, body_, gait_, step_.feet), intent.velocity, dt, landing, motion_);  //  5 body motion: speed
  motion_.on_steps = steps_ahead(ctx, body_, gait_.stride);                    //  5 body motion: steps ahead
  update_gait(rig, params_, motion_.speed, motion_.on_steps, decay_.run, decay_.gait, gait_);  //  6 gait clock
  lean_body(-params_.max_spine_rotation * std::min(motion_.speed / gait_.run_speed, 1.2f), decay_.lean, body_);  // 7 body motion
  const float dx = allowed_move(ctx, body_, pose_.facing, step_.feet, gait_.stride, body_.facing * motion_.speed * dt,
                                body_boxes_, handoff_);
  update_block(handoff_, body_.facing, motion_);
  move_body(dx, body_);
  if (rig.legs.empty()) {                                                       //  8 the legless crawl
    tick_crawl(rig, motion_.speed, motion_.block.blocked, dt, gait_);
    halt_if_blocked(motion_);
  } else {                                                                      //  8 gait clock, step
    tick_clock(rig, anim::gait_family(rig, params_), step_.feet, motion_.speed, motion_.block.blocked, dt, ism, gait_, handoff_.leg_phase);
    step_feet(ctx, spline_prototypes_, body_, gait_, motion_.speed, dt, handoff_, step_);
    update_block(handoff_, body_.facing, motion_);
    halt_if_blocked(motion_);
    advance_feet(ctx, body_, gait_, motion_.speed, dt, handoff_, step_);
  }
  handoff_.crouch_done = tick_crouch(rig, params_, dt, loco_);                  //  9 locomotion: the crouch
  trunk_bob(rig, params_, spline_prototypes_, step_.feet, motion_.speed,       // 10 the girdles' bob
            steady_gait(motion_.on_steps, motion_.block.blocked, step_.feet, handoff_.waiting), dt, gait_);
  place_body(ctx, dt);                                                          // 10 body placement
  if (!rig.legs.empty()) lift_overstretched_feet(ctx, spline_prototypes_, body_, gait_, motion_.speed, handoff_, step_);  // 10b step
  switch (mode_change(ctx, body_, step_.feet, landing, handoff_.crouch_done, loco_, body_state_.body_lift)) {  // 11 locomotion
    case ModeChange::kJump: {  // forwards at the speed asked for, even from a standstill at a step
      const glm::vec2 v = jump_velocity(rig, params_, motion_.speed, std::fabs(intent.velocity), motion_.block.blocked);
      take_off(ctx, body_, {body_.facing * v.x, v.y}, true, step_.feet, loco_);
      leave_ground(ctx, body_, true, loco_.floor, false, step_);
      clear_block(motion_);
      break;
    }
    case ModeChange::kFall:  // stepped off the last foothold
      take_off(ctx, body_, {body_.facing * motion_.speed, 0.0f}, false, step_.feet, loco_);
      leave_ground(ctx, body_, false, loco_.floor, false, step_);
      break;
    case ModeChange::kLanded:
      finish_landing(loco_);
      set_down_after_landing(ctx, body_, gait_, step_);
      break;
    case ModeChange::kNone: break;
  }
  if (below_kill_height(rig, body_, level)) respawn(level);  // came down on a floor at the kill height
  finish_tick(ctx, dt);                                                         // 12 pose
  // Standing or blocked, a part of the body settled or leant a little into a step ahead: the
  // body goes back out of it (moving, the wall sweep keeps it out). Not far: the feet stay
  // where they stand; no further than it came on this tick (a blocked body trying the way
  // ahead again: the frog in the 2 m frame, its skull 3.2 cm into drops.json's 0.7 m step as
  // its body rose). Moving, so does a trunk the stance legs could not lift over the step it
  // came to (random creature 10's rib, 9.9 mm into stairs.json's top riser): it waits there
  // for its feet to climb.
  if (loco_.mode == Locomotion::kGrounded && (!gait_.moving || motion_.block.blocked || handoff_.trunk_left_in)) {
    go_back_from_face(ctx, std::max(std::fabs(dx), kStandingPushOfHip * rig.hip_height));
  }
}

bool Animator::go_back_from_face(const AnimContext& ctx, float most, bool flesh) {
  const bool grounded = loco_.mode == Locomotion::kGrounded;
  // Blocked (or trying the way ahead again), its stance legs' drawn outline too (a triceratops
  // at a post, its shoulder's flesh in the post's corner; a pigeon at a riser, its knee).
  const bool legs = grounded && (motion_.block.blocked || motion_.block.trial > 0.0f);
  const float push = push_back_from_face(ctx, body_, pose_.facing, body_boxes_, flesh, most, legs ? &step_.feet : nullptr,
                                         std::max(most, kStanceFleshPushOfHip * rig().hip_height));
  if (!(push > 0.0f)) return false;
  move_body(-body_.facing * push, body_);
  // On the ground the stance legs must still reach their feet from where the body went (the
  // brachiosaurus retrying the way ahead at drops.json's end wall went 10 cm back, a hind foot
  // drawn 4 mm off its foothold until the next tick's placement).
  if (grounded) keep_stance_feet_in_reach(ctx, placement_inputs(0.0f), step_.feet, handoff_, body_, body_state_);
  finish_tick(ctx, 0.0f);
  return true;
}

// ---- Stage calls with their inputs -------------------------------------------------------------

PlacementInputs Animator::placement_inputs(float dt) const {
  PlacementInputs in;
  in.dt = dt;
  in.speed = motion_.speed;
  in.stepping = gait_.moving;
  in.bob = gait_.girdle_bob;
  in.extra_bob = gait_.extra_bob;
  in.turning = handoff_.turned;
  in.keep_pitch = decay_.pitch;
  in.keep_root = decay_.root;
  in.keep_bob = decay_.bob;
  in.crouch = (loco_.mode == Locomotion::kCrouch ? loco_.crouch : 0.0f) + gait_.pentapedal * rig().pentapedal_crouch;
  in.pitch_down = gait_.pentapedal * rig().pentapedal_pitch;
  in.root = landing_root(loco_);
  in.flex = gait_.spine_flex;
  return in;
}

void Animator::place_body(const AnimContext& ctx, float dt) {
  anim::place_body(ctx, placement_inputs(dt), step_.feet, handoff_, body_, body_state_);
}

namespace {

void prefetch_bytes(const void* p, size_t n) {
#if defined(__GNUC__)
  for (size_t o = 0; o < n; o += 64) __builtin_prefetch(static_cast<const char*>(p) + o);
#else
  (void)p, (void)n;
#endif
}
template <class T>
void prefetch_vector(const std::vector<T>& v) {
  prefetch_bytes(v.data(), v.size() * sizeof(T));
}

}  // namespace

void Animator::prefetch(bool object) const {
  if (object) {
    prefetch_bytes(this, sizeof(*this));
    return;
  }
  prefetch_vector(pose_.pose.locals);
  prefetch_vector(pose_.facing);
  prefetch_vector(pose_.leg_dirs);
  prefetch_vector(step_.feet.feet);
  prefetch_vector(gait_.foot_offset);
  prefetch_vector(gait_.bob_series);
  const std::span<const std::byte> treads = ground_.tread_bytes(), columns = ground_.column_bytes();
  prefetch_bytes(treads.data(), treads.size());
  prefetch_bytes(columns.data(), columns.size());
}

void Animator::finish_tick(const AnimContext& ctx, float dt) {
  // Stage 12: the pose. A legless body its wave bent into the ground rises (body placement)
  // before its limbs are posed; where a box bent its drape (a slab over a neck), it is laid
  // again at the new height, which would otherwise lift the bent bones into the box.
  const HeadMotion head{gait_.head_rise, gait_.head_shift};
  float raise = pose_body(ctx, body_, body_state_.root_vy, gait_.crawl_phase, motion_.speed, dt, pose_, head);
  if (raise > 0.0f && pose_.drape_met_level) {
    raise_body(raise, body_, body_state_);
    raise = pose_body(ctx, body_, body_state_.root_vy, gait_.crawl_phase, motion_.speed, 0.0f, pose_, head);
  }
  if (raise > 0.0f) {
    raise_body(raise, body_, body_state_);
    lift_pose(*rig_, raise, pose_);
  }
  const float motion = std::min(motion_.speed / std::max(gait_.walk_speed, 1e-3f), 1.0f);
  pose_limbs(ctx, spline_prototypes_, body_, step_.feet, gait_, motion, dt, pose_);
}

}  // namespace ossa
