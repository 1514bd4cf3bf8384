#pragma once
// Leg IK (DESIGN.md §7 "leg IK"; part of the pose stage, stage 12 of Animator::update): every
// leg's pose from its contact point and girdle joint. A three-segment leg (a long foot on its
// tip, RigLeg::coupled) is solved whole, its foot coupled to the leg (solve_coupled_leg);
// others roll the foot about its contact point as far as the leg's reach needs (leg_geometry.h
// leg_ankle), then solve upper + lower by analytic two-bone IK. A swinging leg that would cut a box lifts its foot, then tucks
// it, until the whole leg clears; so does a walking creature's stance leg that the body
// placement stretched past its reach (LegIkJob::moving).
//
// Works in facing space (_fs, see anim_state.h): the creature faces +x there, so knees bend
// the right way whichever way it faces. Lengths in metres.

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "ossa/anim/anim_state.h"
#include "ossa/anim/leg_geometry.h"
#include "ossa/math/two_bone_ik.h"
#include "ossa/skeleton/pose.h"

namespace ossa::anim {

// A three-segment leg (RigLeg::coupled) reaching `tip_fs` from `joint_fs` with its foot coupled
// to the leg, the lower joint folded `fold` radians (>= 0) beyond the coupling — less where the
// tip lies too far for that fold. The foot and the bone it follows (forearm or thigh) act as
// one bone, p + q·e^(iγ) in complex terms, so the pose is one analytic two-bone solve. Writes
// the upper and lower directions, the middle joint, the ankle and the foot's direction; false
// (nothing written) where the coupled leg cannot reach the tip: stretched beyond its length,
// or folded closer than it bends.
bool solve_coupled_leg(const RigLeg& info, glm::vec2 joint_fs, glm::vec2 tip_fs, float fold, TwoBoneIkResult* ik,
                       glm::vec2* foot_dir);

// The leg reaching `tip_fs` with its lower joint (ankle, hock) straight: the shin and foot in
// line. False where it cannot reach (as solve_coupled_leg).
bool solve_straight_ankle(const RigLeg& info, glm::vec2 joint_fs, glm::vec2 tip_fs, TwoBoneIkResult* ik, glm::vec2* foot_dir);

// How the leg IK draws stance leg `leg` (LegIkJob::run, the stance part): its foot's contact
// point and girdle joint (_fs), what is near the foot (FootState::stance_clear). A three-
// segment leg coupled, where that pose clears the level; else the foot rolled about its
// contact (leg_ankle), upper and lower solved to the ankle, and the ankle straight where it
// would bend past straight (and that clears). `ankle` is the ankle the legs reach for (the
// IK's end may fall short of it: a leg stretched past its reach).
struct StanceLegPose {
  TwoBoneIkResult ik;
  glm::vec2 foot_dir{0.0f}, ankle{0.0f};
};
StanceLegPose stance_leg_pose(const AnimContext& ctx, const BodyFrame& body, int leg, glm::vec2 contact_fs, glm::vec2 joint_fs,
                              const Clearance& near);

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
  // Input: the gait clock runs (GaitState::moving). A stance leg the body placement stretched
  // past its reach then lifts out of any box it cuts, as a swinging leg does (its foot lifts
  // on the next tick anyway, clamp 6); a standing creature's feet stay where they are drawn.
  bool moving = false;

  bool validate() const;
  bool run() const;
};

}  // namespace ossa::anim
