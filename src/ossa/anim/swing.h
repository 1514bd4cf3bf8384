#pragma once
// Swing (DESIGN.md §7 "swing"; part of the step stage, step.h, stages 2, 4, 8 and A3 of
// Animator::update): a lifted foot's path from where it lifted to its landing —
// the blended walk/run prototype [T 4.4.1] mapped onto the plan, raised until the whole foot
// clears every box [T 5.1e] — and its progress tick by tick until touch-down.
//
// One set-up for every kind of swing (begin_swing): a step (set_new_splines, timed by the gait
// phase), an eased unlifted step (after a stop, or a correction; timed in seconds) and a turn's
// repositioning step. Positions in world space (_ws), metres.

#include <glm/vec2.hpp>

#include "ossa/anim/anim_state.h"
#include "ossa/anim/foothold.h"
#include "ossa/anim/spline_prototypes.h"

namespace ossa::anim {

// The shape and timing of a swing.
struct SwingShape {
  HermiteSpline swing_x, swing_y;  // normalised prototypes: fraction of the step, lift
  float lift = 0.0f;               // metres per unit of swing_y
  float rate = 0.0f;               // progress per unit of phase, or per second when easing
  bool easing = false;
};
// A gait step's shape: the walk/run prototypes blended by run_factor, lifting a leg's length.
SwingShape step_shape(const SplinePrototypes& prototypes, float run_factor, float lift, float rate, bool easing);
// An eased step's shape: straight along the ground, no lift, over stop_ease_time seconds.
SwingShape ease_shape(float ease_time);

// Starts a swing of `foot` from where it stands to `to_ws` and raises it until it clears the
// level; false when no reasonable lift does (the path runs into a wall).
bool begin_swing(const AnimContext& ctx, const BodyFrame& body, int leg, FootState& foot, glm::vec2 to_ws,
                 const SwingShape& shape);

// [T] set_new_splines: at lift-off, plans leg `leg`'s step (landing from the foothold planner
// at the speed given) over swing_phase cycles. False: no foothold or the way is walled off
// (the foot stays; the creature stops).
bool set_new_splines(const FootholdInputs& in, const SplinePrototypes& prototypes, float run_factor, float speed, int leg,
                     FootState& foot, float swing_phase);

// An eased, unlifted step of leg `leg` to `to` (default: the nearest foothold ahead of the
// foot, drawn in to where the leg reaches), timed in seconds rather than phase: setting feet
// down after a stop, and corrections.
void start_ease(const FootholdInputs& in, int leg, FootState& foot, const glm::vec2* to = nullptr);
// start_ease to `spot`, already one path sample into the step on this tick.
void step_to(const FootholdInputs& in, int leg, FootState& foot, glm::vec2 spot);

// A standing creature's stance foot that its leg no longer reaches (the body held up by the
// ground under its girdle) steps, eased, to the nearest place it fits that the leg reaches,
// under its girdle joint; false (the foot stays) when there is none.
bool restep_in_reach(const FootholdInputs& in, int leg, FootState& foot);

// The foot's point at swing progress s in [0, 1].
glm::vec2 swing_point(const FootState& foot, float s);

// Raises the swing's curve until the whole foot (ankle to toe) clears every box; false when
// no reasonable lift does. Updates foot.swing_clear.
bool raise_for_clearance(const AnimContext& ctx, int facing, int leg, FootState& foot);

// What may rise near a standing foot (stance_clear, stance_reach_clear) or a swing's path.
void update_stance_clearance(const AnimContext& ctx, FootState& foot);
void update_swing_clearance(const AnimContext& ctx, int leg, FootState& foot);

// One tick of a swinging foot: an eased step runs on time (dt seconds); a step re-aims while
// the body has been held back (the landing stays half a stance ahead of where the girdle will
// be); at its end the foot moves on to where it fits if it no longer does there (the creature
// turned meanwhile), waits up to kMaxHoverSeconds above a landing the leg cannot yet reach
// while the body comes down to it, then touches down. A landing still out of reach after the
// wait, or beyond the leg's reach across, gives way to the nearest place below the joint that
// the leg reaches. Returns true on touch-down.
struct SwingTick {
  float dt = 0.0f;        // seconds
  float speed = 0.0f;     // m/s along the facing
  bool moving = false;    // the gait clock runs
};
bool advance_swing(const FootholdInputs& in, const SwingTick& tick, int leg, FootState& foot);

// A foot waits above its landing at most this long for the body to come down to it, seconds.
inline constexpr float kMaxHoverSeconds = 0.5f;

// The path is sampled this many times when checked against the level.
inline constexpr int kSwingSamples = 96;

}  // namespace ossa::anim
