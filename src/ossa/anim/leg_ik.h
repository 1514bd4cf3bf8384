#pragma once
// Leg IK (DESIGN.md §7, stage 7): every leg's pose from its contact point and girdle joint —
// the foot rolled about its contact point as far as the leg's reach needs (hooves and toes),
// then analytic two-bone IK on upper + lower. A swinging leg that would cut a box lifts its
// foot, then tucks it, until the whole leg clears.
//
// Works in facing space (_fs, see anim_state.h): the creature faces +x there, so knees bend
// the right way whichever way it faces. Lengths in metres.

#include <array>
#include <vector>

#include <glm/vec2.hpp>

#include "ossa/anim/anim_state.h"
#include "ossa/skeleton/pose.h"

namespace ossa::anim {

// The ankle of leg `leg` for a contact point and girdle joint (_fs), and the foot bone's
// direction: the rest angle unless that over-extends the leg, else pivoted about the contact
// (no further than the level allows, when `level_aware`). *limited: the level kept the foot
// from rolling as far as the leg's reach needs.
glm::vec2 leg_ankle(const AnimContext& ctx, const BodyFrame& body, int leg, glm::vec2 contact_fs, glm::vec2 joint_fs,
                    bool level_aware, const Clearance& near, glm::vec2* foot_dir, bool* limited);

// The point the girdle joint of leg `leg` must stay within *radius of: the contact point
// (foot free to roll) or the ankle (foot held by the level).
glm::vec2 leg_anchor(const AnimContext& ctx, const BodyFrame& body, int leg, glm::vec2 contact_fs, glm::vec2 joint_fs,
                     const Clearance& near, float* radius);

// Would leg `leg`'s chain (joint, knee, ankle, toe), its foot standing where it stands, cut
// into a box with its girdle joint at joint_fs?
bool stance_leg_hits(const AnimContext& ctx, const BodyFrame& body, int leg, const FootState& foot, glm::vec2 joint_fs);

// Poses every leg (ozz-style job: inputs as fields, validate(), run()). Writes the leg bones'
// facing-space matrices and each leg's bone directions (for the joint angles, worked out
// lazily by the animator).
struct LegIkJob {
  const AnimContext* ctx = nullptr;          // input
  const BodyFrame* body = nullptr;           // input
  const FootSet* feet = nullptr;             // input: contact targets and swing/stance state
  const Pose* pose = nullptr;                // input: joint offsets of the leg bones
  std::vector<Mat2x3>* model_fs = nullptr;   // in: girdle matrices; out: leg bone matrices
  std::vector<std::array<glm::vec2, 3>>* leg_dirs = nullptr;  // out: upper, lower, foot directions

  bool validate() const;
  bool run() const;
};

}  // namespace ossa::anim
