#pragma once
// Secondary motion (DESIGN.md §7 "limbs"; the pose stage, pose_stage.h, stage 12 of
// Animator::update, and body placement's bob, stage 10): what follows the body rather than carrying it —
// the tail's damped spring, a legless body lying along the ground, the arms swinging counter to their same-side leg and the fins' slow beat.
//
// Plain functions of the gait and body state; they write joint values of `pose` (radians)
// or return heights (metres).

#include "ossa/anim/anim_state.h"
#include "ossa/anim/animator_params.h"
#include "ossa/anim/gait_clock.h"
#include "ossa/anim/spline_prototypes.h"

namespace ossa::anim {

struct TailSpring {
  float angle = 0.0f;  // radians, summed over the tail
  float rate = 0.0f;   // radians per second
  // What keep_tail_clear last turned the tail by to clear the level (radians: the curl over
  // its length, the lift at its root), held while it clears and settling back.
  float curl = 0.0f, lift = 0.0f;
};
// Advances the tail's spring towards its target (driven by the root's vertical speed root_vy,
// m/s, and the body angle) and bends the tail bones by it.
void swing_tail(const AnimRig& rig, const AnimatorParams& params, float dt, float root_vy, float body_angle, TailSpring& tail,
                Pose& pose);

// A legless body lies along the ground (issue 27): seen from the side a snake's, a whale's
// or a fish's belly follows the ground under it (their undulation is sideways, out of the
// picture). From the root outwards each spine bone turns so that the point it ends at (its
// spine child's joint; at a tip, its own far end) stands its belly's depth over the ground
// profile there (AnimRig::belly, tip_belly), at most kMaxDrapeBend from its rest angle and
// ±kDrapeSlope steep, and turned back as far as what hangs from it (ribs, the skull, a fin's
// root) needs to stay out of the ground; the skull keeps its rest angle, a third of its length
// higher. Where that is not enough the whole body rises (body_out_of_ground). The
// travelling wave at crawl_phase (cycles) lifts short stretches of the body off the ground
// (never into it) by up to params.crawl_amplitude of the half body length, growing with
// `speed` (m/s) up to the walk speed. Ground the profile does not hold, or higher than a
// bone can reach, leaves that bone at its rest angle. A bone so laid that meets a box over it
// (a slab over the drop a neck reaches out over) turns the least that clears it. Writes the
// bones' joint angles and the facing-space matrices of every bone (the root's must be set);
// returns whether a box lay within a hip height over a bone (a body raised after the drape
// would carry that bone into it: drape it again at its new height).
inline constexpr float kDrapeSlope = 0.35f;  // sine of the steepest a draped bone lies
// The skull's far end keeps this share of its length over the ground (its owner's end rises
// with it).
inline constexpr float kHeadLiftOfSkull = 1.0f / 3.0f;
bool drape_legless(const AnimContext& ctx, const BodyFrame& body, float crawl_phase, float speed, Pose& pose,
                   std::vector<Mat2x3>& model_fs);

// Arm swing counter to the same-side leg, scaled by how fast the creature moves; `motion` in
// [0, 1] is the speed as a fraction of the walk speed.
void swing_arm(const AnimRig& rig, const SplinePrototypes& prototypes, const GaitState& gait, const FootSet& feet, const RigLimb& arm,
               float motion, Pose& pose);

// A fin's slow beat at `phase` (cycles).
void beat_fin(const AnimatorParams& params, const RigLimb& fin, float motion, float phase, Pose& pose);

}  // namespace ossa::anim
