#pragma once
// Animator — procedural walking and running for any creature on a box level ([T 4.4]
// generalised to any number of limbs, DESIGN.md §7): a pipeline of stages over an immutable
// AnimRig. animator.cpp only orders the stages and keeps what lasts between ticks; each stage
// is a file pair of its own:
//
//   ground_profile    the level's top surface around the creature as a 1D height profile
//   gait_clock        phase, gait blend by Froude, duty factor, stride, per-leg offsets
//   turn              a command against the facing mirrors the creature in place
//   locomotion        grounded → airborne → landing; the jump's crouch and take-off
//   body_motion       how far the body moves: the wall sweep, then the legs' reach
//   foothold          where a lifting foot lands (lift-off, stop, turn and reset alike)
//   swing             the blended prototype mapped onto the plan, raised until it clears
//   body_placement    girdle heights, pitch and lean; named clamps in a documented order
//   leg_ik            two-bone IK over all legs, foot roll
//   limb_clearance    arms, fins, wings and the tail kept out of the level
//   secondary_motion  bob, tail spring, crawl wave, arm swing, fin beat
//   animator_pose     the pose and forward kinematics (stage 9), the lazily computed outputs
//
// Spaces — one suffix, one meaning:
//   _ws  world: metres, +x right, +y up.
//   _ms  model: the creature's rest frame (DESIGN.md §3), y = 0 on the rest ground, facing +x.
//   _fs  facing: world height, x from the root along the facing direction (the creature faces
//        +x). model_matrices() are in this space: world = model_to_world() · facing.
//   _ls  local to the parent bone.
//
// Everything is deterministic: the same inputs give bit-identical poses.

#include <array>
#include <cstdint>
#include <cmath>
#include <memory>
#include <vector>

#include "ossa/anim/anim_rig.h"
#include "ossa/anim/anim_state.h"
#include "ossa/anim/animator_params.h"
#include "ossa/anim/body_placement.h"
#include "ossa/anim/gait_clock.h"
#include "ossa/anim/ground_profile.h"
#include "ossa/anim/locomotion.h"
#include "ossa/anim/secondary_motion.h"
#include "ossa/anim/spline_prototypes.h"
#include "ossa/gen/creature.h"
#include "ossa/level/level.h"
#include "ossa/skeleton/pose.h"

namespace ossa {

// What the creature is asked to do on one tick.
struct AnimatorIntent {
  float velocity = 0.0f;  // m/s, signed along x
  bool jump = false;      // the jump button went down on this tick (a grounded creature jumps)
};

class Animator {
 public:
  // Builds the creature's rig (build_anim_rig) for this animator alone.
  Animator(const Creature& creature, SplinePrototypes prototypes, AnimatorParams params = {});
  // Shares a rig built once for many animators of the same creature.
  Animator(const Creature& creature, std::shared_ptr<const AnimRig> rig, SplinePrototypes prototypes, AnimatorParams params = {});
  // Drives any rig: a rigged character's (character.h) or one built from roles by hand. No
  // Creature behind it: has_creature() is false.
  Animator(std::shared_ptr<const AnimRig> rig, SplinePrototypes prototypes, AnimatorParams params = {});

  // Stands the creature on the ground below `position_ws` (x, and a height to search down
  // from: spawn points lie on the ground, tools start a metre above), feet under their
  // girdles, facing +x (facing = 1) or -x (-1). Ground further below than kResetSnap (or
  // none) and the creature falls from `position_ws`, feet hanging, and lands. Clears the
  // locomotion stats.
  void reset(glm::vec2 position_ws, const Level& level, int facing = 1);
  // How far below the reset position the ground may lie for the creature to stand on it: this
  // many hip heights, and at least kResetSnapMin metres.
  static constexpr float kResetSnapOfHip = 2.0f, kResetSnapMin = 1.5f;

  // One fixed step of dt seconds towards intent.velocity, jumping when asked. A creature that
  // falls below the level's kill height starts again at the level's spawn.
  void update(float dt, const AnimatorIntent& intent, const Level& level);
  void update(float dt, float desired_velocity, const Level& level) { update(dt, AnimatorIntent{desired_velocity, false}, level); }

  // ---- [T] tuning -------------------------------------------------------------------------
  const SplinePrototypes& spline_prototypes() const { return spline_prototypes_; }
  // New prototypes take effect at each leg's next lift-off (set_new_splines).
  void set_spline_prototypes(const SplinePrototypes& prototypes) { spline_prototypes_ = prototypes; }
  AnimatorParams& params() { return params_; }
  const AnimatorParams& params() const { return params_; }

  // ---- Output -----------------------------------------------------------------------------
  // The generated creature this animator was made for (the first two constructors only).
  bool has_creature() const { return creature_ != nullptr; }
  const Creature& creature() const;
  const AnimRig& rig() const { return *rig_; }
  const std::shared_ptr<const AnimRig>& shared_rig() const { return rig_; }
  // The joint values of the current pose (the legs' angles are worked out on first use after
  // an update: the matrices below do not need them).
  const Pose& pose() const;
  // Facing space → world: a mirror of x by the facing and the root's world x.
  Mat2x3 model_to_world() const;
  // Facing-space (_fs) matrices of the current pose. update() computes the bones it needs
  // (spine to the girdles, limbs); the rest (ribs, neck, skull, tail...) on first use after an
  // update, so headless simulation and ticks between rendered frames do not pay for them.
  const std::vector<Mat2x3>& model_matrices() const;
  // World matrices of the current pose: model_to_world() · facing-space, computed on first
  // use after an update (renderers that fold the placement into their palette never pay).
  const std::vector<Mat2x3>& world_matrices() const;
  // The ground profile of the last tick (stage 1).
  const GroundProfile& ground_profile() const { return ground_; }

  // ---- State ------------------------------------------------------------------------------
  float x() const { return body_.x_ws; }               // world x of the root
  float velocity() const { return body_.facing * speed_; } // m/s, signed
  int facing() const { return body_.facing; }
  Gait gait() const { return gait_.gait; }
  float froude() const { return gait_.froude; }
  float stride_length() const { return gait_.stride; } // metres per cycle
  float duty_factor() const { return gait_.duty; }
  float cycle_frequency() const { return gait_.frequency; } // cycles per second
  float run_factor() const { return gait_.run_factor; }     // walk→run blend in [0, 1]
  bool blocked() const { return block_.blocked; }
  int steps() const { return steps_; }                 // touch-downs so far
  float hip_height() const { return rig_->hip_height; } // h of the Froude number, metres
  // The walk's reference speed (Froude 0.5) and the full run's (Froude 2.5: a gallop for two
  // or more leg pairs), m/s, and where the gaits change.
  float walk_speed() const { return anim::walk_speed(*rig_, params_); }
  float run_speed() const { return anim::run_speed(*rig_, params_); }
  anim::GaitBands gait_bands() const { return anim::gait_bands(*rig_, params_); }

  // ---- Locomotion mode (locomotion.h) -----------------------------------------------------
  Locomotion locomotion() const { return loco_.mode; }
  bool airborne() const { return loco_.mode == Locomotion::kAirborne; }
  // Falls, jumps, landings, the highest fall and jump, seconds in the air since the reset.
  const anim::LocomotionStats& locomotion_stats() const { return loco_.stats; }
  // The root's vertical speed in the air and while landing, m/s (0 on the ground).
  float vertical_speed() const { return loco_.mode == Locomotion::kAirborne || loco_.mode == Locomotion::kLanding ? loco_.vy : 0.0f; }
  float root_y() const { return body_.root_y_ws; }     // world y of the root

  int leg_count() const { return static_cast<int>(rig_->legs.size()); }
  // [T] leg_state: stance or swing of leg i.
  LegState leg_state(int leg) const { return feet_.of_leg(leg).state; }
  // The creature's limb that leg i is (has_creature() only).
  const Limb& leg_limb(int leg) const;
  // Where leg i's contact point (tip, or heel for flat contact) is meant to be, world space.
  glm::vec2 foot_target_ws(int leg) const { return feet_.of_leg(leg).pos_ws; }
  // The contact point the pose actually reaches (from the matrices).
  glm::vec2 foot_ws(int leg) const;
  // Progress of leg i's swing in [0, 1] (0 while in stance).
  float swing_progress(int leg) const {
    const anim::FootState& f = feet_.of_leg(leg);
    return f.state == LegState::kSwing ? f.progress : 0.0f;
  }
  // True while the leg sets down after a stop (a short eased swing, not a step).
  bool easing(int leg) const { return feet_.of_leg(leg).easing; }

 private:
  struct BlockState {                // the creature stopped at a wall or a step too tall
    bool blocked = false;
    int dir = 0;                     // the facing it stopped in
    int leg = 0;                     // the leg that found no foothold
    float retry = 0.0f;              // seconds until the way ahead is tested again
  };
  struct Decay {                     // exp(-rate·dt) of each smoothed quantity, per (dt, ism)
    float dt = -1.0f, ism = -1.0f;
    float lean = 0.0f, run = 0.0f, gait = 0.0f, pitch = 0.0f, root = 0.0f;
  };

  anim::AnimContext context(const Level& level) { return {*rig_, params_, level, ground_, hits_}; }
  void refresh_ground(const Level& level);
  void block(int leg);
  bool way_ahead_open(const Level& level, float speed);
  void step_legs(float dt, float ism, const Level& level);
  void advance_swings(float dt, const Level& level);
  anim::PlacementInputs placement_inputs(float dt, bool turned) const;
  void place_body(float dt, bool turned, const Level& level);
  void fly(float dt, const Level& level);
  void end_landing(const Level& level);
  void respawn(const Level& level);
  bool below_kill_height(const Level& level) const;
  void build_pose(float dt, const Level& level);
  void body_fk();

  const Creature* creature_ = nullptr;
  std::shared_ptr<const AnimRig> rig_;
  std::vector<int> leg_limb_;        // per leg: its index in creature().limbs (if any)
  SplinePrototypes spline_prototypes_;
  AnimatorParams params_;

  // State kept between ticks.
  anim::BodyFrame body_;
  anim::BodyState body_state_;
  anim::GaitState gait_;
  anim::FootSet feet_;
  anim::TickHandoff handoff_;
  anim::TailSpring tail_;
  BlockState block_;
  anim::LocomotionState loco_;
  std::uint64_t level_revision_ = 0; // the level's revision the feet last stood on
  GroundProfile ground_;
  Decay decay_;
  float speed_ = 0.0f;               // m/s along the facing
  float idle_time_ = 0.0f;           // seconds
  float crawl_phase_ = 0.0f;         // cycles
  int steps_ = 0;

  // Pose buffers.
  mutable Pose pose_;
  std::vector<std::array<glm::vec2, 3>> leg_dirs_;  // per leg: upper, lower, foot directions (_fs)
  mutable bool leg_angles_dirty_ = false;
  mutable std::vector<Mat2x3> model_;  // facing space
  mutable std::vector<Mat2x3> world_;
  mutable bool world_dirty_ = true;
  mutable bool model_dirty_ = true;    // bones outside rig().tick_bone are stale

  // Scratch.
  std::vector<int> hits_;
  std::vector<Box> body_boxes_;
};

}  // namespace ossa
