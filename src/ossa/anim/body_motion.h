#pragma once
// Body motion: how far the body moves along x on this tick. Two limits, in this order:
//   1. the wall sweep: the body's outline (slabs of the spine, head, arm shoulders and reach,
//      fins) swept along dx stops at a wall; low obstacles are the legs' business (steps);
//   2. the legs: no stance foot is left further behind than its leg reaches (on steps, than
//      kStepReach of it), nor a swinging foot further than its leg reaches; a stance foot
//      below and behind on stairs whose leg would cut a step marks itself to lift.
// Inputs: the rig, params, level, the body frame, the facing-space matrices of the last pose
// (for the outline), the feet. Outputs: the allowed dx (world metres, signed) and hand-offs.

#include <vector>

#include "ossa/anim/anim_state.h"
#include "ossa/skeleton/pose.h"

namespace ossa::anim {

struct BodyMotionResult {
  float dx = 0.0f;         // world metres, signed by the facing
  bool hit_wall = false;   // the sweep met a wall (the creature is blocked)
};

// The wall sweep of dx. `boxes` is scratch. whole: every part from its bottom (in the air,
// where no obstacle is the legs' business).
BodyMotionResult sweep_body(const AnimContext& ctx, const BodyFrame& body, const std::vector<Mat2x3>& model_fs, float dx,
                            std::vector<Box>& boxes, bool whole = false);

// Limits dx so that the legs keep up; marks in handoff.lift_now the feet that must lift.
float limit_by_legs(const AnimContext& ctx, const BodyFrame& body, const FootSet& feet, float dx, TickHandoff& handoff);

// Limits dx so that no girdle joint passes over the face of a ledge its legs cannot climb: a
// riser (ground profile) ahead of the joint beyond which the ground stays more than a
// climbable step above the girdle's feet for a whole stride. A high body would otherwise pass
// over the ledge's top with its feet below (a bird walking back to a ledge it came down), and
// its legs would cross the ledge's corner. A bump the feet step over is not a ledge.
float limit_by_ledges(const AnimContext& ctx, const BodyFrame& body, const FootSet& feet, float stride, float dx);

// World boxes of the body's parts: slabs of the spine, head, arms, fins (slabs = true), or one
// box around them all.
void body_boxes(const AnimRig& rig, const BodyFrame& body, const std::vector<Mat2x3>& model_fs, bool slabs,
                std::vector<Box>* boxes);

}  // namespace ossa::anim
