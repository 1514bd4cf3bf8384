#pragma once
// The values the animator's stages pass each other (DESIGN.md §7):
//   AnimContext  what every stage reads and none writes during a tick (rig, params, level,
//                ground profile);
//   BodyFrame    where the body is: root position, facing, pitch and lean. Written only by
//                body placement's functions (body_placement.h); read by every stage;
//   FootState    one per foot, lasting between ticks. Written only by the step stage (step.h,
//                foothold.h, swing.h, turn.h) through its named transitions; read by others;
//   TickHandoff  what one stage tells a later one on this tick (or, where a field says so,
//                the next), as named fields with their writer and readers.
// animator.h lists every piece of state that lasts between ticks with its owning stage.
//
// Spaces (one suffix, one meaning; see also animator.h):
//   _ws  world: metres, +x right, +y up;
//   _ms  model: the rest frame of DESIGN.md §3, y = 0 on the rest ground, facing +x;
//   _fs  facing: world height, x measured from the root along the facing direction, so the
//        creature faces +x (x_fs = (x_ws - root x) · facing, y_fs = y_ws). The IK and the pose
//        work here: knees bend the right way whichever way the creature faces.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "ossa/anim/anim_rig.h"
#include "ossa/anim/level_probe.h"
#include "ossa/math/hermite.h"

namespace ossa {

class GroundProfile;
struct AnimatorParams;
enum class LegState : uint8_t { kStance, kSwing };

namespace anim {

struct AnimContext {
  const AnimRig& rig;
  const AnimatorParams& params;
  const Level& level;
  const GroundProfile& ground;
  std::vector<int>& hits;  // scratch for level queries (no stage keeps anything in it)
};

struct BodyFrame {
  float x_ws = 0.0f;        // world x of the root
  int facing = 1;           // +1 faces +x, -1 faces -x
  float root_y_ws = 0.0f;   // world y of the root
  float pitch = 0.0f;       // root rotation from the terrain, radians (counter-clockwise, _fs)
  float lean = 0.0f;        // lean into the motion, radians
  float flex = 0.0f;        // the spine's flexion (GaitState::spine_flex), radians

  glm::vec2 to_fs(glm::vec2 p_ws) const { return {(p_ws.x - x_ws) * facing, p_ws.y}; }
  glm::vec2 to_ws(glm::vec2 p_fs) const { return {x_ws + facing * p_fs.x, p_fs.y}; }
  // v rotated by the body angle pitch + lean.
  glm::vec2 rotate_body(glm::vec2 v) const {
    const float angle = pitch + lean;
    if (angle != cached_angle_) {
      cached_angle_ = angle;
      cs_ = {std::cos(angle), std::sin(angle)};
    }
    return {cs_.x * v.x - cs_.y * v.y, cs_.y * v.x + cs_.x * v.y};
  }
  // A rest-pose point (_ms) where the body is now, lifted by `lift` metres (_ws).
  glm::vec2 body_point_ws(const AnimRig& rig, glm::vec2 rest_ms, float lift = 0.0f) const {
    const glm::vec2 j = rotate_body(rest_ms - glm::vec2(0.0f, rig.root_rest_y));
    return to_ws({j.x, j.y + root_y_ws + lift});
  }
  // Girdle joint g with the spine as flexed now (model space) and from the current body
  // placement (world).
  glm::vec2 girdle_ms(const AnimRig& rig, int g) const { return rig.girdle_joint(g, flex); }
  glm::vec2 girdle_ws(const AnimRig& rig, int g) const { return body_point_ws(rig, girdle_ms(rig, g)); }

 private:
  mutable float cached_angle_ = 0.0f;
  mutable glm::vec2 cs_{1.0f, 0.0f};  // cos, sin of cached_angle_
};

// A girdle's joint in facing space for a loop over the legs (a girdle's legs come one after
// another): worked out once per girdle while the body stays where it is. One per loop; stale
// once the body moves.
struct GirdleJointFs {
  int girdle = -1;
  glm::vec2 joint_fs{0.0f};
  glm::vec2 of(const AnimRig& rig, const BodyFrame& body, int g) {
    if (g != girdle) {
      girdle = g;
      joint_fs = body.to_fs(body.girdle_ws(rig, g));
    }
    return joint_fs;
  }
};

// One foot, lasting between ticks. Written only by the step stage's transitions (step.h);
// their invariants, checked by foot_consistent():
//   air (hanging, no landing)  ⇒ state == kSwing, not easing, hover == 0;
//   hang_beyond is a number    ⇒ air (a foot stepping off a ledge);
//   tucked                     ⇒ air;
//   easing                     ⇒ state == kSwing.
struct FootState {
  LegState state = LegState::kStance;
  std::uint32_t plantings = 0;      // times it was set down (a swing's touch-down, plant()): a
                                    // new stance, for a probe that samples less often than the
                                    // animator steps (a tick of substeps)
  glm::vec2 pos_ws{0.0f};           // contact point target
  glm::vec2 from_ws{0.0f}, to_ws{0.0f};
  HermiteSpline swing_x, swing_y;   // blended prototypes of this swing (set_new_splines)
  float lift = 0.0f;                // metres per unit of swing_y
  float raise = 0.0f;               // extra clearance bump, metres
  float progress = 0.0f;            // swing progress s in [0, 1]
  float rate = 0.0f;                // ds per unit of phase (or per second when easing)
  bool easing = false;              // a stop: progress runs on time, not on phase
  float hover = 0.0f;               // seconds spent waiting above the landing point
  // Hanging in the air with no landing (stepping off a drop, falling, after pushing off): the
  // foot follows its girdle (step.h air_target) and is planted where it meets the ground.
  // air_offset, from the air target, eases to nothing, so the foot does not jump when it
  // leaves the ground.
  bool air = false;
  glm::vec2 air_offset{0.0f};       // metres (_ws)
  float hang_beyond = NAN;          // stepping off: the world x the hanging foot reaches past
  bool tucked = false;              // hung over a drop, tucked up at a turn that took its girdle
                                    // back over the ledge: it draws the girdle down nowhere
  float floor = 1e30f;              // a fall's feet are planted only on ground below this (_ws)
  float stood_y = NAN;               // the height it last stood at (_ws), for note_ledge
  // Stepped down off a ledge this high, more than a step up (_ws; NaN: none): while a foot still
  // stands on it, this one may step back up to it (foothold.h step_limits).
  float ledge_y = NAN;
  // What may rise near the foot (level_probe.h), cached for the level revision the feet last
  // saw (StepState::level_revision): around pos_ws in stance, within a leg's reach of it in
  // stance, and around the path of the current swing.
  Clearance stance_clear;
  Clearance stance_reach_clear;
  Clearance swing_clear;
};

// The feet and which leg stands on which (turning round hands feet between leg pairs).
struct FootSet {
  std::vector<FootState> feet;
  std::vector<int> foot_of_leg;
  FootState& of_leg(int leg) { return feet[foot_of_leg[leg]]; }
  const FootState& of_leg(int leg) const { return feet[foot_of_leg[leg]]; }
};

// A foot's place in the gait cycle on this tick (gait_clock.h advance_leg_phase).
struct LegPhase {
  float phase = 0.0f;     // the foot's local phase, cycles in [0, 1)
  bool lift_due = false;  // a standing foot's phase crossed the duty factor: it lifts
};

// What a stage tells a later one, on this tick unless a field says otherwise. Animator::update
// clears the per-tick fields at its start (begin_tick); each field names its writer and
// readers.
inline constexpr uint8_t kLiftNow = 1, kLiftIfPlaced = 2;  // TickHandoff::lift_now

struct TickHandoff {
  // Per leg, while the gait clock runs: its foot's phase and whether its lift-off is due.
  // Writer: the gait clock (tick_clock). Reader: the step stage.
  std::vector<LegPhase> leg_phase;
  // Per foot: standing behind and below its girdle on stairs, its leg would cut a step, so it
  // lifts at its next chance (kLiftNow); or only its drawn flesh would, so it lifts if it
  // finds a foothold, else stands (kLiftIfPlaced). Writer: body motion (limit_by_legs).
  // Reader: the step stage's lift decision, later on this tick.
  std::vector<uint8_t> lift_now;
  // Per foot: a stance leg the body placement stretched past its reach (clamps 1 and 6), or
  // left with its thigh or shin across an edge (clamp 3), lifts at its next chance instead of
  // sliding or standing in the step. Lasts to the next tick: written wholly by body
  // placement (cleared at its start, on every call); read by the step stage's lift decision
  // and its re-step of a standing creature on the next tick.
  std::vector<uint8_t> release_next;
  // Per foot: waiting above its landing for the body to come down to it (the swing's hover).
  // Writer: the step stage (end of its tick). Reader: body placement (girdle heights).
  std::vector<uint8_t> waiting;
  // The creature turned round on this tick. Writer: the orchestrator's turn decision.
  // Readers: body placement (takes its new height and pitch at once; swinging feet count).
  bool turned = false;
  // A wall or a ledge the body cannot pass stopped it. Writer: body motion. Reader: the block
  // (body_motion.h MotionState), at once.
  bool wall_ahead = false;
  // The leg whose lift-off found no foothold and no drop (a wall too tall, the way walled
  // off), or -1. Writer: the step stage. Reader: the block, after the step stage.
  int no_foothold_leg = -1;
  // The crouch before a jump is over: take off at the end of the tick. Writer: locomotion
  // (advance_crouch, before body placement). Reader: locomotion's take-off, after it.
  bool crouch_done = false;
  // Feet that met the ground while airborne on this tick. Writer: the step stage's air feet.
  // Reader: locomotion's touch-down test.
  int planted = 0;
  // A bone of the trunk was left in a box: it needed the body to rise further than the stance
  // legs reach. Writer: body placement (clamp 5). Reader: the orchestrator, which takes the
  // body back out of the box's face at the end of the tick.
  bool trunk_left_in = false;

  void resize(size_t feet) {
    lift_now.assign(feet, 0);
    release_next.assign(feet, 0);
    waiting.assign(feet, 0);
  }
  void begin_tick() {
    std::fill(lift_now.begin(), lift_now.end(), 0);
    std::fill(waiting.begin(), waiting.end(), 0);
    turned = wall_ahead = crouch_done = trunk_left_in = false;
    no_foothold_leg = -1;
    planted = 0;
  }
};

}  // namespace anim
}  // namespace ossa
