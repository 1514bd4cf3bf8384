#pragma once
// The step stage (DESIGN.md §7): the one writer of the feet. It is the foothold planner
// (foothold.h: where a lifting foot lands), the swing (swing.h: the path there) and the
// transitions of a foot between standing, swinging and hanging, written here once each:
//
//   lift     a stance foot starts a swing (swing.h begin_swing: a step, an eased set-down, a
//            turn's repositioning step);
//   touch    a swing ends where it was planned (swing.h advance_swing);
//   hang     a foot leaves the ground with no landing: stepping off a drop, a fall, a jump;
//   plant    a hanging foot meets the ground;
//   unhang   a hanging foot is set down by a step of its own (a landing's end, a turn);
//   hand     a turn round hands the feet to the leg pairs that now stand over them (turn.h).
// Their invariants (anim_state.h FootState) are checked by foot_consistent().
//
// The stage runs at several points of Animator::update (animator.cpp numbers them): the
// level's changes (stage 2), the turn (stage 4), the lift-offs and swings (stage 8), and in the
// air the push-off and the feet reaching for the ground (stage A3). Other stages read the feet
// (const FootSet&) and tell this one what they need through TickHandoff.
//
// Positions in world space (_ws), metres; times in seconds.

#include <cstdint>

#include <glm/vec2.hpp>

#include "ossa/anim/anim_state.h"
#include "ossa/anim/foothold.h"
#include "ossa/anim/gait_clock.h"
#include "ossa/anim/spline_prototypes.h"

namespace ossa::anim {

// Owned by the step stage: the feet, and what it counts and caches about them.
struct StepState {
  FootSet feet;
  int steps = 0;                     // touch-downs since the reset
  std::uint64_t level_revision = 0;  // the level revision the feet's clearance caches are for
};

// The foothold planner's inputs for the feet as they stand, the body and the gait as they are.
inline FootholdInputs planner(const AnimContext& ctx, const BodyFrame& body, const GaitState& gait, const FootSet& feet) {
  return {ctx, body, gait.stride, gait.duty, &feet};
}

// ---- Transitions of one foot -----------------------------------------------------------------

// Where leg `leg`'s foot hangs in the air: under its girdle, tucked (extension 0) or reaching
// for the ground (1), a front leg ahead and a hind leg behind.
glm::vec2 air_target(const AnimContext& ctx, const BodyFrame& body, int leg, float extension);

// hang: the foot leaves the ground from where it is (no jump: its offset from the air target
// eases away). Its clearance cache knows nothing then: the leg IK tests the hanging leg.
void hang(const AnimContext& ctx, const BodyFrame& body, int leg, float extension, FootState& foot);
// plant: a hanging foot stands at p (the ledge a fall left, if any, is remembered).
void plant(const AnimContext& ctx, FootState& foot, glm::vec2 p);
// unhang: a hanging foot stops hanging where it is, to be set down by a step of its own.
void unhang(FootState& foot);

// Do the foot's fields keep the invariants of FootState (anim_state.h)?
bool foot_consistent(const FootState& foot);

// ---- The stage on a tick ------------------------------------------------------------------------

// Animator::reset: every foot under its girdle at the ground below (or, `falling`, where the
// body is, about to hang), each where it fits; the counts cleared.
void reset_feet(const AnimContext& ctx, const BodyFrame& body, const GaitState& gait, float ground_y_fallback,
                float search_from_y, float search_depth, bool falling, StepState& step);

// Stage 2: the level changed under the feet (its revision moved). A standing foot whose
// ground went hangs; every foot's clearance cache is worked out again.
void watch_level(const AnimContext& ctx, const BodyFrame& body, StepState& step);

// Stage 8, on the ground. While the creature moves and is not blocked: the gait clock's
// lift-offs (leg_phase, per leg, from gait_clock.h tick_clock), each planning its step — or,
// where no foothold is, stepping off a drop or stopping the creature (handoff.no_foothold_leg)
// — and the swings' progress by the clock. Standing: swinging feet set down eased, and a foot
// the body placement stretched past its reach re-steps. Then every swing advances, and the
// feet hanging over a drop reach down.
// `gait` has ticked (gait_clock.h tick_clock: GaitState::moving, handoff.leg_phase); `speed`
// is the speed asked for (m/s), dt seconds.
void step_feet(const AnimContext& ctx, const SplinePrototypes& prototypes, const BodyFrame& body, const GaitState& gait,
               float speed, float dt, TickHandoff& handoff, StepState& step);
// Stage 10b, after body placement: a stance foot the placement has just stretched out of its
// leg's reach (handoff.release_next, clamp 6: a stance knee raised out of the ground, a body
// held up by the ground under it) lifts — or, standing, re-steps — on this tick rather than
// the next, so it is not dragged for a tick by a leg that cannot reach it (a slide). Other
// released feet lift on the next tick (step_feet), as does one with no foothold ahead.
void lift_overstretched_feet(const AnimContext& ctx, const SplinePrototypes& prototypes, const BodyFrame& body,
                             const GaitState& gait, float speed, const TickHandoff& handoff, StepState& step);
// The swings' progress after step_feet (the block may have stopped the creature meanwhile:
// `speed` 0), then the hanging feet; fills handoff.waiting. A foot that waited in vain above
// a landing out of its leg's reach, while another foot of its girdle stands higher than the
// leg straddles, hangs instead of touching down.
void advance_feet(const AnimContext& ctx, const BodyFrame& body, const GaitState& gait, float speed, float dt,
                  TickHandoff& handoff, StepState& step);

// The body leaves the ground (locomotion.h take_off): a jump's stance feet but the front ones
// of a quadruped keep pushing off (push_off_and_reach), every other foot hangs; `floor`: a
// fall lands only below it. from_rest: placed in the air by a reset, the feet hang right
// where they are.
void leave_ground(const AnimContext& ctx, const BodyFrame& body, bool jump, float floor, bool from_rest, StepState& step);
// Stage A3, in the air: feet still on the ground push off until their legs are stretched, or
// at once when the body no longer rises (vy, m/s, its vertical speed); then the hanging feet
// follow their girdles, reaching for the ground by `extension` (locomotion.h
// reach_extension), and those that meet it on the way down are planted (handoff.planted).
void push_off_and_reach(const AnimContext& ctx, const BodyFrame& body, float vy, float extension, float dt,
                        TickHandoff& handoff, StepState& step);
// The landing is over: feet that found no ground as the body came down set down where they can;
// one with no ground to step to hangs on.
void set_down_after_landing(const AnimContext& ctx, const BodyFrame& body, const GaitState& gait, StepState& step);

// Feet hanging in the air follow their targets and are planted where they meet the top of a
// box on the way down; reach_ground (on the ground: stepping off, landing): a foot reaches
// down to ground its leg reaches below it; may_land false (the body still rising): a foot
// meeting ground is carried along it, not planted; in the air and falling, a foot with no
// ground below it in its leg's reach goes over the edge of a ledge ahead that the leg reaches
// and comes down on its top. Returns how many were planted.
int update_air_feet(const AnimContext& ctx, const BodyFrame& body, float extension, float dt, bool reach_ground,
                    FootSet& feet, bool may_land = true);

}  // namespace ossa::anim
