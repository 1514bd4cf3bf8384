#pragma once
// Secondary motion (DESIGN.md §7 "limbs"; the pose stage, pose_stage.h, stage 12 of
// Animator::update, and body placement's bob, stage 10): what follows the body rather than carrying it —
// the tail's damped spring, the travelling wave of legless
// bodies, the arms swinging counter to their same-side leg and the fins' slow beat.
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
};
// Advances the tail's spring towards its target (driven by the root's vertical speed root_vy,
// m/s, and the body angle) and bends the tail bones by it.
void swing_tail(const AnimRig& rig, const AnimatorParams& params, float dt, float root_vy, float body_angle, TailSpring& tail,
                Pose& pose);

// The legless travelling wave at crawl_phase (cycles) and speed (m/s).
void crawl_wave(const AnimRig& rig, const AnimatorParams& params, float crawl_phase, float speed, Pose& pose);

// Arm swing counter to the same-side leg, scaled by how fast the creature moves; `motion` in
// [0, 1] is the speed as a fraction of the walk speed.
void swing_arm(const AnimRig& rig, const SplinePrototypes& prototypes, const GaitState& gait, const FootSet& feet, const RigLimb& arm,
               float motion, Pose& pose);

// A fin's slow beat at `phase` (cycles).
void beat_fin(const AnimatorParams& params, const RigLimb& fin, float motion, float phase, Pose& pose);

}  // namespace ossa::anim
