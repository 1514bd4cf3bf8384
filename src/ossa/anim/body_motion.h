#pragma once
// Body motion (DESIGN.md §7; stages 5 and 7 of Animator::update): how fast the creature goes
// and how far the body may move along x on this tick. Owns MotionState: the speed and the
// block (stopped at a wall or a step too tall). The move itself is body placement's
// (body_placement.h move_body). Two limits on the move, in this order:
//   1. the wall sweep: the body's outline (slabs of the spine, head, arm shoulders and reach,
//      fins) swept along dx stops at a wall; low obstacles are the legs' business (steps);
//   2. the legs: no stance foot is left further behind than its leg reaches (on steps, than
//      kStepReach of it), nor a swinging foot further than its leg reaches; a stance foot
//      below and behind on stairs whose leg would cut a step is told to lift
//      (TickHandoff::lift_now);
// then no girdle passes over the face of a ledge its legs cannot climb.
// Inputs: the rig, params, level, the body frame, the facing-space matrices of the last pose
// (for the outline), the feet. Outputs: the allowed dx (world metres, signed) and hand-offs.

#include <cmath>
#include <vector>

#include "ossa/anim/anim_state.h"
#include "ossa/anim/foothold.h"
#include "ossa/skeleton/pose.h"

namespace ossa::anim {

// Owned by body motion: lasts between ticks.
struct MotionState {
  float speed = 0.0f;              // m/s along the facing
  struct Block {                   // the creature stopped at a wall or a step too tall
    bool blocked = false;
    int dir = 0;                   // the facing it stopped in
    int leg = 0;                   // the leg that found no foothold
    float retry = 0.0f;            // seconds until the way ahead is tested again
    // Seconds a retry that found a way ahead still counts as blocked for the report (the way
    // may turn out not to be one a tick later: the message does not blink off meanwhile).
    float trial = 0.0f;
  } block;
  // Steps under or a stride ahead of the body (steps_ahead): the fast gait gives way to the
  // middle one (gait clock).
  bool on_steps = false;
};

// Stage 5: the speed for the stick. It sets the speed precisely [T 4.1]; starting and stopping
// are immediate [T 5.1] (the half-length first step and the eased stop make them read well); a
// landing's descent holds the body still. A blocked creature stays stopped while the command
// keeps its direction, and tests the way ahead again now and then (the level may have
// changed; `in`: the planner as the feet stand).
void command_speed(const FootholdInputs& in, float desired_velocity, float dt, bool landing, MotionState& motion);

// Stage 5: is there a riser taller than a tenth of the hip height between the body's back end
// and a stride (metres) ahead of its front? Animals take steps and stairs in their walk, trot
// or half-bound rather than a gallop or a bound; the gait clock's fast gait waits for level
// ground.
bool steps_ahead(const AnimContext& ctx, const BodyFrame& body, float stride);

// Stage 7: how far the body may move this tick, for a wish of dx (world metres, signed):
// the wall sweep, the legs and the ledges (above). Sets handoff.wall_ahead when a wall or a
// ledge stopped it, and handoff.lift_now for feet that must lift. `boxes` is scratch.
float allowed_move(const AnimContext& ctx, const BodyFrame& body, const std::vector<Mat2x3>& model_fs, const FootSet& feet,
                   float stride, float dx, std::vector<Box>& boxes, TickHandoff& handoff);

// Stages 7 and 8: a wall or ledge ahead (handoff.wall_ahead) or a leg that found no foothold
// (handoff.no_foothold_leg) blocks the creature, facing `facing`.
void update_block(const TickHandoff& handoff, int facing, MotionState& motion);
// Stage 8: a blocked creature stands (after the legless wave has moved on at the speed asked).
inline void halt_if_blocked(MotionState& motion) {
  if (motion.block.blocked) motion.speed = 0.0f;
}
// Stage 11: a jump takes off whatever blocked the way; A1: in the air the speed is the path's.
inline void clear_block(MotionState& motion) {
  motion.block.blocked = false;
  motion.block.trial = 0.0f;
}
inline void follow_path(float vx, MotionState& motion) { motion.speed = std::fabs(vx); }

struct BodyMotionResult {
  float dx = 0.0f;         // world metres, signed by the facing
  bool hit_wall = false;   // the sweep met a wall (the creature is blocked)
};

// A trunk bone (AnimRig::trunk) lying more than this many hip heights under the top of a box
// where it crosses it lies in a wall: the trunk clamp (body placement, clamp 5) lifts it out by
// less, and on the ground the wall sweep stops the body before a bone comes so deep.
inline constexpr float kMaxTrunkRaiseOfHip = 0.5f;

// The wall sweep of dx. `boxes` is scratch. whole: every part from its bottom (in the air,
// where no obstacle is the legs' business).
BodyMotionResult sweep_body(const AnimContext& ctx, const BodyFrame& body, const std::vector<Mat2x3>& model_fs, float dx,
                            std::vector<Box>& boxes, bool whole = false);

// Limits dx so that the legs keep up; marks in handoff.lift_now the feet that must lift.
float limit_by_legs(const AnimContext& ctx, const BodyFrame& body, const FootSet& feet, float dx, TickHandoff& handoff);

// Limits dx so that no girdle joint passes over the face of a ledge its legs cannot climb: a
// riser (ground profile) ahead of the joint beyond which the ground stays more than a
// climbable step above the girdle's feet for a whole stride. A high body would otherwise pass
// over the ledge's top with its feet below (a bird walking back to a ledge it came down), and
// its legs would cross the ledge's corner. A bump the feet step over is not a ledge.
float limit_by_ledges(const AnimContext& ctx, const BodyFrame& body, const FootSet& feet, float stride, float dx);

// World boxes of the body's parts: slabs of the spine (a bone each for a rig without slabs: a
// legless body), head, arms, fins (slabs = true), or one box around them all.
void body_boxes(const AnimRig& rig, const BodyFrame& body, const std::vector<Mat2x3>& model_fs, bool slabs,
                std::vector<Box>* boxes);

}  // namespace ossa::anim
