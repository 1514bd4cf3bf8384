#pragma once
// Limb clearance (DESIGN.md §7 "limbs"; part of the pose stage, pose_stage.h, stage 12 of
// Animator::update): the limbs that do not stand keep out of the level —
// arms lift their wrists above the ground or fold (tucked under the shoulder, up in front,
// up behind), fins and folded wings turn up at the root, a tail curls up out of a step, a head
// lifts on its neck, and a legless body bent by its wave rises out of the ground.
//
// Each works on the joint values of `pose` (the limb's bones) and the facing-space matrices
// of the body already placed; world queries through the body frame. Metres, radians.

#include <vector>

#include "ossa/anim/anim_state.h"
#include "ossa/skeleton/pose.h"

namespace ossa::anim {

struct TailSpring;  // (secondary_motion.h)

// `margin`: how far above the ground the arm keeps, metres (RigScale::arm_margin; less for a
// hand that stands on the ground, pentapedal.h). with_flesh: its drawn outline too
// (RigLimb::flesh_outline; not for a hand that stands on its palm).
void keep_arm_above_ground(const AnimContext& ctx, const BodyFrame& body, const RigLimb& arm, const std::vector<Mat2x3>& model_fs,
                           float margin, Pose& pose, bool with_flesh = true);
void keep_fin_clear(const AnimContext& ctx, const BodyFrame& body, const RigLimb& fin, const std::vector<Mat2x3>& model_fs,
                    Pose& pose);
// `tail` holds the turn it last took (TailSpring::curl, lift): kept, settling back over `dt`
// seconds (0: a pose again within the tick), while it still clears.
void keep_tail_clear(const AnimContext& ctx, const BodyFrame& body, const std::vector<Mat2x3>& model_fs, float dt, TailSpring& tail,
                     Pose& pose);
// A head (neck, skull, jaw) the body placed in the ground or a step lifts at the neck's base
// (AnimRig::nod_bones[0]), the least that clears, the skull kept level.
void keep_head_clear(const AnimContext& ctx, const BodyFrame& body, const std::vector<Mat2x3>& model_fs, Pose& pose);
// Legless bodies: returns how far the whole body must rise (metres, >= 0) so the spine and
// the roots of its limbs stay out of the ground.
float body_out_of_ground(const AnimContext& ctx, const BodyFrame& body, const std::vector<Mat2x3>& model_fs, const Pose& pose);

}  // namespace ossa::anim
