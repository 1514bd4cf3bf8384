#pragma once
// The pentapedal walk (GaitFamilyTraits::pentapedal; issue 28, GAITS.md "hoppers"): slowly, a
// kangaroo leans down onto its forelimbs and tail. Its hind feet move together; while they
// swing forward the hands and the tail's tip are planted and hold the body (Dawson & Taylor
// 1973; O'Connor et al. 2014: the tail pushes as a leg does), and while the hind feet stand
// the hands swing forward to their next place and the tail lifts a little.
//
// Stages: the lean (how far the body has gone down, GaitState::pentapedal) eases with the gait
// (ease_pentapedal, with the bob, stage 10); body placement pitches the body nose down and
// lowers its girdle by that share of the rig's pentapedal_pitch and pentapedal_crouch; the
// pose plants the hands (two-bone IK, the hand laid flat forward) and presses the tail's tip
// down to the ground (press_tail, plant_hands, with the limbs, stage 12).

#include <vector>

#include <glm/vec2.hpp>

#include "ossa/anim/anim_rig.h"
#include "ossa/anim/anim_state.h"
#include "ossa/anim/gait_clock.h"
#include "ossa/skeleton/pose.h"

namespace ossa::anim {

// Per arm: where its hand is planted (world; swinging, where the swing takes it, on the
// ground), where its swing began, and whether it stands.
struct PentapedalHand {
  glm::vec2 at{0.0f}, from{0.0f};
  bool planted = false;
  bool known = false;  // `at` holds a place (not on the first tick of the walk)
};

// Owned by the pose stage (PoseState): the hands' places.
struct PentapedalState {
  std::vector<PentapedalHand> hands;  // per AnimRig::arms
};

// The rig's pentapedal posture (AnimRig::pentapedal_pitch, pentapedal_crouch), for the
// builder: one leg girdle with arms only.
void build_pentapedal(AnimRig& rig);

// Eases gait.pentapedal (a critically damped spring) towards the walk's share of the gait (1 − mid_factor) while the
// family walks on five supports and the creature moves in a steady gait (trunk_bob.h,
// steady_gait): a kangaroo that stops stays down on its hands and tail, as one grazing does,
// and one blocked, on steps or at a ledge keeps its posture (rising there would swing its
// back into the step); it rises as it breaks into the hop.
void ease_pentapedal(bool steady, float dt, GaitState& gait);

// The pose's part, blended with what the pose already holds by gait.pentapedal: the tail
// pressed down (before its clearance) and the arms planted or swinging (after their swing).
// `model` holds the body's facing-space matrices (the arms' girdles, the tail's base).
void press_tail(const AnimContext& ctx, const BodyFrame& body, const FootSet& feet, const GaitState& gait,
                const std::vector<Mat2x3>& model, Pose& pose);
// How far above the ground the arms keep (keep_arm_above_ground): RigScale::arm_margin, down
// to a touch as the body goes down onto its hands.
float hand_margin(const AnimRig& rig, const GaitState& gait);
void plant_hands(const AnimContext& ctx, const BodyFrame& body, const FootSet& feet, const GaitState& gait,
                 const std::vector<Mat2x3>& model, PentapedalState& state, Pose& pose);

}  // namespace ossa::anim
