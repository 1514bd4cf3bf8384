#pragma once
// Body placement's own parts, shared by its two files (not a public header): the Placement
// being worked out on this tick, the constants of the targets and the clamps, and the clamps
// in their order (body_clamps.cpp; the targets and place_body are in body_placement.cpp).

#include <cstdint>
#include <vector>

#include "ossa/anim/body_placement.h"

namespace ossa::anim::placement {

inline constexpr float kMaxPitch = 0.9f;       // the body turns no steeper than this (radians)
inline constexpr float kMaxPitchStep = 0.03f;  // nor by more than this in one tick to keep a foot in reach
inline constexpr float kMaxPitchOff = 0.25f;   // nor further than this from the pitch of the ground
inline constexpr float kMaxTargetPitch = 0.7f; // the pitch target between two girdles, radians
// A girdle over a higher step rises with it halfway; the ground is looked for over this
// fraction of its rest height either side.
inline constexpr float kGirdleGroundHalfOfRest = 0.2f;
// A stance leg's girdle never comes down below this fraction of its rest height above the foot.
inline constexpr float kLowestGirdleOfRest = 0.6f;
// A foot behind and below dragging the body down by more than this fraction of its girdle's
// rest height lifts on the next tick.
inline constexpr float kDragLiftOfRest = 0.05f;
// A girdle keeps this fraction of its rest height above the highest ground under it, looked
// for over kGirdleKeepOutHalfOfRest either side.
inline constexpr float kGirdleKeepOutOfRest = 0.12f;
inline constexpr float kGirdleKeepOutHalfOfRest = 0.1f;
// Beyond that window the ground's claim fades by this many rest heights below its top.
inline constexpr float kKeepOutFadeOfRest = 0.25f;
// The box tops alone (no fade to speak of), where a girdle's keep-out margin yields.
inline constexpr float kNoFadeOfRest = 1e-6f;
// A shoulder keeps this many hip heights above the ground under it.
inline constexpr float kShoulderKeepOutOfHip = 0.1f;
// A knee keeps this fraction of its leg's reach above the ground within kKneeHalfWidth (m).
inline constexpr float kKneeMarginOfReach = 0.02f;
inline constexpr float kKneeHalfWidth = 0.001f;
// A single girdle's body looks this many seconds ahead for ground rising under its shoulder.
inline constexpr float kShoulderLookAhead = 0.25f;
// A foot hanging over a drop draws its girdle down to ground this many contact reaches below it.
inline constexpr float kHangGroundOfReach = 1.5f, kHangDipOfRest = 0.35f;
// A legless body follows the ground under it and this many seconds of travel ahead.
inline constexpr float kLeglessLookAhead = 0.2f;
// The lift the legless wave last needed settles back at this rate (1/s), so that the body
// follows the ground down a step; on level ground, where every wave needs the same lift,
// slower: held, the body is not pulled down and lifted again at every wave (the
// ichthyosaurus's crawl jolted 1.6 g at 1/s).
inline constexpr float kLeglessLiftSettle = 1.0f, kLeglessLiftSettleLevel = 0.5f;
// On level ground, only once a whole crawl wave (the body travelling its half length) has
// passed with no raise: the lift a wave needs comes back with the next, and settled in between
// it came back at once (random creature 26's pelvis, 5 cm in three ticks every wave, 8.7 g).
// Standing, at most this many seconds.
inline constexpr float kLeglessLiftHoldMax = 4.0f;
// BodyState::knee_lift settles back at this rate (1/s).
inline constexpr float kKneeLiftSettle = 0.5f;
// The bob dips the body by at most this share of its trunk's room over what lies under it
// freely; deeper it eases into the rest of that room (ease_dip_over_trunk).
inline constexpr float kBobFreeOfTrunkRoom = 0.5f;
// One tick raises no girdle by more than this many hip heights to clear a knee, in at most
// kKneePasses passes.
inline constexpr float kMaxKneeRaiseOfHip = 0.5f;
// A stance leg whose thigh or shin clamp 3 leaves across an edge by more than this (metres,
// vertically) lifts at the next chance: below the probe's millimetre however it grows in a tick.
inline constexpr float kStanceCrossRelease = 0.0004f;
inline constexpr int kKneePasses = 6;
// A swinging knee's raise that would take a stance foot out of reach is halved up to this many
// times (then dropped: the swing tucks the leg instead).
// Clamp 1 vouches for a stance foot's reach (so clamp 6 need not test it) only this far inside
// it, metres.
inline constexpr float kReachCheckSlack = 1e-4f;
// Ground this many climbable steps above the ground under a girdle is a wall to its keep-out.
inline constexpr float kKeepOutStepsOfClimb = 1.5f;
inline constexpr int kSwingRaiseHalvings = 5;
// ... while it leaves no stance foot further than this (metres; under the slip tolerance) beyond
// its reach than it was.
inline constexpr float kSwingRaiseSlack = 5e-4f;

struct Placement {
  const AnimContext& ctx;
  const PlacementInputs& in;
  const FootSet& feet;
  BodyFrame& body;
  BodyState& state;
  // Per foot: waiting above its landing (TickHandoff::waiting, read).
  const std::vector<uint8_t>& waiting;
  // Per foot: stretched past its reach, lifts next tick (TickHandoff::release_next, written by
  // the clamps; nullptr when only the targets are worked out).
  std::vector<uint8_t>* release = nullptr;
  // Set when clamp 5 leaves a trunk bone in a box (TickHandoff::trunk_left_in; nullptr: not asked).
  bool* trunk_left_in = nullptr;
  // Clamp 1 left every stance foot within its leg's reach, the body as it was then: clamp 6
  // has nothing to release while the later clamps do not move the body.
  bool reach_checked = false;
  float checked_root = 0.0f, checked_pitch = 0.0f;
};

// Moves girdle g's joint up by dy, turning the body about the girdle at the other end.
void move_girdle(Placement& p, int g, float dy);
// A girdle joint's keep-out (body_clamps.cpp, clamp 5).
float girdle_keep_out_top(const AnimContext& ctx, glm::vec2 joint_ws, float rest, float extra);
float girdle_keep_out(const AnimContext& ctx, glm::vec2 joint_ws, float rest, float extra);
// How far the trunk's bones (AnimRig::trunk, the skull kept level), with the body placed as
// now and lifted by `lift`, need the body to rise to keep clear of the boxes they are in, and
// the turn up about `pivot_ws` that would do it for the bones ahead of it (body_clamps.cpp).
// A bone needing half a hip height or more meets a wall and is left to the wall sweep.
struct TrunkNeed {
  float raise = 0.0f;  // metres
  float pitch = 0.0f;  // radians up about `pivot`: the same for the bones ahead of it
};
TrunkNeed trunk_need(const AnimContext& ctx, const BodyFrame& body, float lift, glm::vec2 pivot_ws);

// The clamps, in their order (body_placement.h).
void keep_stance_legs_in_reach(Placement& p, std::vector<float>& need, std::vector<float>& room);
void keep_stance_legs_unfolded(Placement& p, std::vector<float>& fold_raise, std::vector<float>& room);
void keep_knees_off_ground(Placement& p, std::vector<float>& stance_up, std::vector<float>& swing_up, std::vector<float>& room);
void pitch_for_front_shoulder(Placement& p);
void keep_body_out_of_ground(Placement& p, float fell, const std::vector<float>& room);
void release_overstretched_feet(Placement& p);

}  // namespace ossa::anim::placement
