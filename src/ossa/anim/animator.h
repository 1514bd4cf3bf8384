#pragma once
// Animator — procedural walking and running for any creature on a box level ([T 4.4]
// generalised to any number of limbs, DESIGN.md §7): a pipeline of stages over an immutable
// AnimRig. Each stage is a file pair of its own; animator.cpp runs them in the order of its
// numbered stage list (Animator::update) and keeps the state between ticks, one owner each:
//
//   member        state                    owner (its stages)             read by
//   ground_       GroundProfile            ground profile (1), keyed on   every stage after it
//                                            the level's revision
//   step_         StepState: the feet,     the step stage (2, 4, 8, A3):  gait clock, body motion,
//                   touch-downs, the level   step.h, turn.h, swing.h,       body placement,
//                   revision they saw        foothold.h                     locomotion, pose
//   loco_         LocomotionState: mode,   locomotion (3, 9, 11, A1,      the orchestrator (which
//                   crouch, air path,        A4, A5): locomotion.h          branch), body placement
//                   landing, counts                                         (crouch, landing)
//   motion_       MotionState: speed,      body motion (5, 7, 8):         gait clock, step stage,
//                   block                    body_motion.h                  body placement, pose
//   gait_         GaitState: phase,        gait clock (6, 8):             step stage, body
//                   blends, stride, foot     gait_clock.h                   placement (bob), pose
//                   offsets, idle & crawl
//   body_,        BodyFrame, BodyState     body placement (4, 7, 10, 12,  every stage
//   body_state_                              A2, A4): body_placement.h
//   pose_         PoseState: pose, tail    the pose stage (12):           the outputs below
//                   spring, matrices         pose_stage.h
//   handoff_      TickHandoff              per tick; each field names its writer and readers
//                                            (anim_state.h)
//   decay_        Decay                    the orchestrator: smoothing factors cached per
//                                            (dt, ism), derived state
//
// Spaces — one suffix, one meaning:
//   _ws  world: metres, +x right, +y up.
//   _ms  model: the creature's rest frame (DESIGN.md §3), y = 0 on the rest ground, facing +x.
//   _fs  facing: world height, x from the root along the facing direction (the creature faces
//        +x). facing_matrices() are in this space: world = facing_to_world() · facing.
//   _ls  local to the parent bone.
//
// Everything is deterministic: the same inputs give bit-identical poses.

#include <array>
#include <cstdint>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "ossa/anim/anim_rig.h"
#include "ossa/anim/anim_state.h"
#include "ossa/anim/animator_params.h"
#include "ossa/anim/body_motion.h"
#include "ossa/anim/body_placement.h"
#include "ossa/anim/gait_clock.h"
#include "ossa/anim/ground_profile.h"
#include "ossa/anim/locomotion.h"
#include "ossa/anim/pose_stage.h"
#include "ossa/anim/spline_prototypes.h"
#include "ossa/anim/step.h"
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
  // falls below the level's kill height starts again at the level's spawn. A creature whose
  // gait cycles in fewer than 16 such steps (a frog at true size), or that falls more than a
  // tenth of its hip height in one, takes the step in up to 8 equal substeps, so that its
  // motion does not depend on the tick rate.
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
  const Pose& pose() const { return anim::pose_angles(*rig_, pose_); }
  // Facing space → world: a mirror of x by the facing and the root's world x.
  Mat2x3 facing_to_world() const { return anim::facing_to_world(body_); }
  // Facing-space (_fs) matrices of the current pose. update() computes the bones it needs
  // (spine to the girdles, limbs); the rest (ribs, neck, skull, tail...) on first use after an
  // update, so headless simulation and ticks between rendered frames do not pay for them.
  const std::vector<Mat2x3>& facing_matrices() const { return anim::facing_matrices(*rig_, pose_); }
  // World matrices of the current pose: facing_to_world() · facing-space, computed on first
  // use after an update (renderers that fold the placement into their palette never pay).
  // Asks the processor to bring this animator's per-tick state into its cache: a herd
  // (step_all) steps thousands of animators one after another, each one's state long evicted
  // since its last tick; asked a few creatures ahead, the memory's latency overlaps the work.
  // `object`: the animator itself (its members say where the rest lies), else the arrays.
  void prefetch(bool object) const;
  const std::vector<Mat2x3>& world_matrices() const { return anim::world_matrices(*rig_, body_, pose_); }
  // The ground profile of the last tick (stage 1).
  const GroundProfile& ground_profile() const { return ground_; }
  // What the stages told each other on the last tick (anim_state.h TickHandoff): for tools and
  // tests that follow the pipeline.
  const anim::TickHandoff& last_tick() const { return handoff_; }

  // ---- State ------------------------------------------------------------------------------
  float x() const { return body_.x_ws; }               // world x of the root
  float velocity() const { return body_.facing * motion_.speed; } // m/s, signed
  int facing() const { return body_.facing; }
  Gait gait() const { return gait_.gait; }
  float froude() const { return gait_.froude; }
  float stride_length() const { return gait_.stride; } // metres per cycle
  float duty_factor() const { return gait_.duty; }
  float cycle_frequency() const { return gait_.frequency; } // cycles per second
  float run_factor() const { return gait_.run_factor; }     // walk→run blend in [0, 1]
  // Per girdle (rig().girdles, front first): how high the footfalls make it ride over its
  // standing height this tick (trunk_bob.h), metres.
  const std::vector<float>& girdle_bob() const { return gait_.girdle_bob; }
  bool blocked() const { return motion_.block.blocked; }
  // Why it stands blocked, for a HUD or a log (worked out when asked, from the ground the
  // last tick saw): the ground from its root to a body length past its front, against its
  // leading feet, what its legs climb and step down and how high its jump rises. A creature
  // small for the level says so.
  struct BlockReport {
    bool blocked = false;   // blocked(), or trying the way ahead again for up to half a second
    float rise_m = 0.0f;    // the highest ground ahead above its leading feet (0: none higher)
    float drop_m = 0.0f;    // the deepest ground ahead below them (INFINITY: a gap)
    float climb_m = 0.0f;   // the highest step its legs climb (params().max_step_up)
    float step_down_m = 0.0f;  // the deepest step down its legs take (params().max_step_down)
    float jump_m = 0.0f;    // how high its jump rises (jump_rise, locomotion.h)
  };
  BlockReport block_report() const;
  int steps() const { return step_.steps; }            // touch-downs so far
  float hip_height() const { return rig_->hip_height; } // h of the Froude number, metres
  // The gait family it moves by (params().gait_family, else the rig's: never kAuto).
  GaitFamily gait_family() const { return anim::gait_family(*rig_, params_); }
  // The walk's reference speed (Froude 0.5, less for slow families) and the full run's (the
  // family's top Froude), m/s, and where the family's gaits change.
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
  LegState leg_state(int leg) const { return step_.feet.of_leg(leg).state; }
  // Times leg i's foot was set down since the reset: a change between two looks is a new stance
  // even when the foot stands at both (a tick of substeps may hold a whole swing).
  std::uint32_t plantings(int leg) const { return step_.feet.of_leg(leg).plantings; }
  // The creature's limb that leg i is (has_creature() only).
  const Limb& leg_limb(int leg) const;
  // Where leg i's contact point (tip, or heel for flat contact) is meant to be, world space.
  glm::vec2 foot_target_ws(int leg) const { return step_.feet.of_leg(leg).pos_ws; }
  // The contact point the pose actually reaches (from the matrices).
  glm::vec2 foot_ws(int leg) const;
  // Progress of leg i's swing in [0, 1] (0 while in stance).
  float swing_progress(int leg) const {
    const anim::FootState& f = step_.feet.of_leg(leg);
    return f.state == LegState::kSwing ? f.progress : 0.0f;
  }
  // True while the leg sets down after a stop (a short eased swing, not a step).
  bool easing(int leg) const { return step_.feet.of_leg(leg).easing; }
  // Leg i's foot as the step stage keeps it (read-only: for tools and tests).
  const anim::FootState& foot_state(int leg) const { return step_.feet.of_leg(leg); }

 private:
  struct Decay {                     // exp(-rate·dt) of each smoothed quantity, per (dt, ism)
    float dt = -1.0f, ism = -1.0f;
    float lean = 0.0f, run = 0.0f, gait = 0.0f, pitch = 0.0f, root = 0.0f, bob = 0.0f;
  };

  anim::AnimContext context(const Level& level) { return {*rig_, params_, level, ground_, hits_}; }
  anim::PlacementInputs placement_inputs(float dt) const;
  void place_body(const anim::AnimContext& ctx, float dt);
  void finish_tick(const anim::AnimContext& ctx, float dt);
  // One step of the pipeline (update splits a tick into these).
  void tick(float dt, const AnimatorIntent& intent, const Level& level);
  static constexpr int kSubstepsPerCycle = 16;
  static constexpr int kMaxSubsteps = 8;
  static constexpr float kFallStepOfHip = 0.1f;
  // A part of the body in a box ahead (push_back_from_face): the body goes back out of it,
  // if that takes no more than `most` metres, and is posed again (flesh: its drawn flesh
  // counts too). Whether it went.
  bool go_back_from_face(const anim::AnimContext& ctx, float most, bool flesh = false);
  void respawn(const Level& level);

  const Creature* creature_ = nullptr;
  std::shared_ptr<const AnimRig> rig_;
  std::vector<int> leg_limb_;        // per leg: its index in creature().limbs (if any)
  SplinePrototypes spline_prototypes_;
  AnimatorParams params_;

  // State kept between ticks, one owner each (the table at the top of this file).
  GroundProfile ground_;
  anim::StepState step_;
  anim::LocomotionState loco_;
  anim::MotionState motion_;
  anim::GaitState gait_;
  anim::BodyFrame body_;
  anim::BodyState body_state_;
  anim::PoseState pose_;
  anim::TickHandoff handoff_;
  Decay decay_;

  // Scratch.
  std::vector<int> hits_;
  std::vector<Box> body_boxes_;
};

// One line for a HUD or a log saying why the creature stands blocked ("" when it is not): a
// step too high for its legs (and whether a jump would rise over it), a drop too deep, a gap,
// or a wall.
std::string describe_block(const Animator::BlockReport& report);

}  // namespace ossa
