#pragma once
// Body placement (DESIGN.md §7): the owner of the body — BodyFrame (where it is) and BodyState
// — and the one writer of both. Its main work is stage 10 of Animator::update, place_body: the
// root's height, the body's pitch and lean from where the feet are. Each girdle's height = the
// ground under its feet + its standing height + the pelvis bob; the spine pitches between the
// girdles. Then the clamps, as named functions in this order (body_clamps.cpp; a later one may
// only raise what an earlier one lowered, never undo a hard limit):
//   1. keep_stance_legs_in_reach   lower a girdle (turning the body about the other end) so
//                                  that no stance leg over-extends; hard, not smoothed;
//   2. keep_stance_legs_unfolded   raise the body so no stance leg folds tighter than it can;
//   3. keep_knees_off_ground       raise a girdle until each knee clears the ground (a
//                                  swinging leg's knee only as far as 1. leaves room; a
//                                  knee only within its margin of flat ground eased); a
//                                  stance leg it leaves across an edge lifts at the next
//                                  chance (TickHandoff::release_next);
//   4. pitch_for_front_shoulder    a single girdle's shoulder far ahead turns the body up;
//   5. keep_body_out_of_ground     girdles, shoulders and folded wings stay above the ground,
//                                  and the trunk's bones (ribs, neck, skull) as far as the
//                                  stance legs reach (a body its hind girdle alone holds
//                                  up turns up about it);
//   6. release_overstretched_feet  a stance leg the raising clamps stretched past its reach
//                                  lifts at the next chance (TickHandoff::release_next).
// The other stages move the body only through the transitions below, each where
// Animator::update's stage list calls it: the reset, the turn (stage 4), the lean and the
// step along x that body motion allowed (stage 7), the path in the air (stage A2), the body
// meeting the ground before its feet (A4) and a legless body lifted out of the ground by its
// wave (stage 12).
//
// Inputs: AnimContext, the feet, the gait, the bob; in/out: the body frame and BodyState.
// Heights in world metres; angles radians.

#include <cmath>
#include <span>

#include <glm/vec2.hpp>

#include "ossa/anim/anim_state.h"
#include "ossa/anim/gait_clock.h"

namespace ossa::anim {

// Owned by body placement, with BodyFrame.
struct BodyState {
  float pitch_target = 0.0f;  // the pitch of the ground under the girdles, radians
  float root_vy = 0.0f;       // vertical speed of the root, m/s (drives the tail)
  float body_lift = 0.0f;     // legless: how far the wave has lately lifted the body, metres
  float lift_hold = 0.0f;     // legless: crawl waves left before body_lift may settle (1 at a raise)
  // Legged, over level ground: how far the knee clamp has lately raised the body above its
  // target, metres, held in the target and settling back slowly (a sprawling leg's knee meets
  // the ground in every stance: the body stays up rather than drop and be raised each stride).
  float knee_lift = 0.0f;
  // The part of the root height and the pitch the girdles' bob gave last tick: the placement
  // smooths the rest (steps, slopes) and adds the bob unsmoothed (a low-pass would flatten and
  // delay a trot's bounce).
  float bob_root = 0.0f, bob_pitch = 0.0f;
  // The rest chord between the end girdles (model space) the placement last used, and its
  // length and angle: worked out once, not every tick.
  glm::vec2 chord{NAN, NAN};
  float chord_length = 0.0f, chord_angle = 0.0f;
};

struct PlacementInputs {
  float dt = 0.0f;            // seconds; 0 places at once (reset)
  float speed = 0.0f;         // m/s along the facing
  bool stepping = false;      // the gait clock runs this tick (a released foot lifts, not resteps)
  std::span<const float> bob;  // per girdle: the footfalls' bob (trunk_bob.h), metres, unsmoothed
  float extra_bob = 0.0f;      // every girdle: the pelvis_y prototype's bob or idle breathing, metres
  bool turning = false;       // this tick mirrored the creature (swinging feet count as stance; the
                              // pitch may stay as the turn left it: move_girdle)
  float keep_pitch = 0.0f;    // smoothing exp(-rate·dt) of the pitch and the root height
  float keep_root = 0.0f;
  float keep_bob = 0.0f;      // smoothing of the bob's part (BodyState::bob_root, bob_pitch)
  float crouch = 0.0f;        // the girdles stand this much lower (a jump's crouch), metres
  float root = NAN;           // a landing's descent: the root's height this tick, not smoothed
  float flex = 0.0f;          // the spine's flexion (GaitState::spine_flex), radians
  float pitch_down = 0.0f;    // one girdle: the body leans nose down by this much (the pentapedal walk), radians
};

// Stage 10: places the body over the feet. Reads handoff.waiting; writes handoff.release_next
// (every foot's, cleared first).
void place_body(const AnimContext& ctx, const PlacementInputs& in, const FootSet& feet, TickHandoff& handoff, BodyFrame& body,
                BodyState& state);

// The body moved along the ground after place_body (pushed back out of a face, standing):
// clamp 1 again, its stance legs kept in reach, and clamp 6's release of any it cannot keep.
void keep_stance_feet_in_reach(const AnimContext& ctx, const PlacementInputs& in, const FootSet& feet, TickHandoff& handoff,
                               BodyFrame& body, BodyState& state);

// The root height place_body aims for with the feet where they are, before its smoothing and
// clamps (the standing height a landing comes down towards), metres.
float standing_root(const AnimContext& ctx, const PlacementInputs& in, const FootSet& feet, const TickHandoff& handoff,
                    const BodyFrame& body);

// ---- The body's other transitions -------------------------------------------------------------

// The reset: the root at (x, root_y), facing `facing`, level, still.
void reset_body(float x, float root_y, int facing, BodyFrame& body, BodyState& state);
// The turn (turn.h): the front and back girdles swap places, each as high over the other's
// ground as it stood over its own, the pitch following (a body pitched down a ledge stays along
// it); a legless body keeps the stretch of ground it lies on in its pose `model_fs`
// (facing-space model matrices). The facing flips, no lean.
void mirror_body(const AnimRig& rig, const std::vector<Mat2x3>& model_fs, BodyFrame& body);
// Stage 7: the lean into the motion eases towards `lean` (radians; keep = exp(-rate·dt)).
void lean_body(float lean, float keep, BodyFrame& body);
// Stages 7 and A2: the root moves dx along x (world metres, signed), as body motion allowed.
void move_body(float dx, BodyFrame& body);
// Stage A2: the root at its height on the path in the air (root_y, rising at vy m/s), pitch
// and lean easing level (keep_level = exp(-rate·dt)).
void fly_body(float root_y, float vy, float keep_level, BodyFrame& body, BodyState& state);
// Stage A4: the body meeting the ground before any foot (the legless, short legs on a slope)
// stands on it there (true). A girdle still over the ledge a fall left (ground at `floor` or
// above) does not land on it: the body tips over its edge instead, turning about the front
// girdle.
bool rest_body_on_ground(const AnimContext& ctx, float floor, BodyFrame& body);
// Stage 12: a legless body whose wave bent it into the ground rises by `raise` metres.
void raise_body(float raise, BodyFrame& body, BodyState& state);

}  // namespace ossa::anim
