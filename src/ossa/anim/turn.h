#pragma once
// Turning round [T 4.4.1, 5.1] (stage 4 of Animator::update): a command against the facing
// mirrors the creature in place. Two owners act, in this order:
//   body placement (body_placement.h mirror_body): the root shifts so that the front and back
//     girdles land on each other's feet, the facing flips, the lean is dropped;
//   the step stage (turn_feet, here): the feet keep their world positions; leg pairs take
//     over the feet standing where their girdle now is (girdle i ← girdle n-1-i, same side);
//     a leg whose foot is then out of reach steps under its girdle; a foot that would reach
//     into a step takes a quick step to where it fits.
// The body takes its new height and pitch at once on this tick (TickHandoff::turned: body
// placement's snap).

#include "ossa/anim/anim_state.h"
#include "ossa/anim/gait_clock.h"
#include "ossa/anim/spline_prototypes.h"

namespace ossa::anim {

// Does a command of `velocity` (m/s, signed along x) turn a creature facing `facing` round? Not
// while a landing's descent holds the body, nor for a stick at rest.
inline bool turn_wanted(float velocity, int facing, bool landing) {
  constexpr float kTurnSpeed = 1e-4f;  // m/s
  const int want = velocity > kTurnSpeed ? 1 : velocity < -kTurnSpeed ? -1 : 0;
  return !landing && want != 0 && want != facing;
}

// The step stage's part of a turn, the body already mirrored (`body`): the feet handed to the
// legs now over them, feet hanging in the air unhung, and the re-steps above.
void turn_feet(const AnimContext& ctx, const SplinePrototypes& prototypes, const GaitState& gait, const BodyFrame& body,
               FootSet& feet);

}  // namespace ossa::anim
