#pragma once
// Body placement (DESIGN.md §7, stage 6): the root's height, the body's pitch and lean from
// where the feet are. Each girdle's height = the ground under its feet + its standing height
// + the pelvis bob; the spine pitches between the girdles. Then the clamps, as named
// functions in this order (a later one may only raise what an earlier one lowered, never
// undo a hard limit):
//   1. keep_stance_legs_in_reach   lower a girdle (turning the body about the other end) so
//                                  that no stance leg over-extends; hard, not smoothed;
//   2. keep_stance_legs_unfolded   raise the body so no stance leg folds tighter than it can;
//   3. keep_knees_off_ground       raise a girdle until each knee clears the ground (a
//                                  swinging leg's knee only as far as 1. leaves room);
//   4. pitch_for_front_shoulder    a single girdle's shoulder far ahead turns the body up;
//   5. keep_body_out_of_ground     girdles, shoulders and folded wings stay above the ground;
//   6. release_overstretched_feet  a stance leg the raising clamps stretched past its reach
//                                  lifts at the next chance (TickHandoff::lift_now).
//
// Inputs: AnimContext, the feet, the gait, the bob; in/out: the body frame and BodyState.
// Heights in world metres; angles radians.

#include <cmath>

#include "ossa/anim/anim_state.h"
#include "ossa/anim/gait_clock.h"

namespace ossa::anim {

struct BodyState {
  float pitch_target = 0.0f;  // the pitch of the ground under the girdles, radians
  float root_vy = 0.0f;       // vertical speed of the root, m/s (drives the tail)
  float body_lift = 0.0f;     // legless: how far the wave has lately lifted the body, metres
  // The rest chord between the end girdles (model space) the placement last used, and its
  // length and angle: worked out once, not every tick.
  glm::vec2 chord{NAN, NAN};
  float chord_length = 0.0f, chord_angle = 0.0f;
};

struct PlacementInputs {
  float dt = 0.0f;            // seconds; 0 places at once (reset)
  float speed = 0.0f;         // m/s along the facing
  float bob = 0.0f;           // pelvis bob (or idle breathing), metres
  bool snap = false;          // take the new height and pitch at once (a turn)
  bool turning = false;       // this tick mirrored the creature (swinging feet count as stance)
  float keep_pitch = 0.0f;    // smoothing exp(-rate·dt) of the pitch and the root height
  float keep_root = 0.0f;
  float crouch = 0.0f;        // the girdles stand this much lower (a jump's crouch), metres
  float root = NAN;           // a landing's descent: the root's height this tick, not smoothed
};

void place_body(const AnimContext& ctx, const PlacementInputs& in, const FootSet& feet, BodyFrame& body, BodyState& state,
                TickHandoff& handoff);

// The root height place_body aims for with the feet where they are, before its smoothing and
// clamps (the standing height a landing comes down towards), metres.
float standing_root(const AnimContext& ctx, const PlacementInputs& in, const FootSet& feet, const BodyFrame& body);

}  // namespace ossa::anim
