#pragma once
// The pose stage (DESIGN.md §7 stages "leg IK", "limbs" and "pose + FK"; stage 12 of
// Animator::update): the joint values of the pose and the facing-space matrices the renderer
// reads. In this order:
//   pose_body   the body's joints: the root at the body frame, the skull kept level, the tail's
//               spring and the legless wave (secondary_motion.h), then the body's forward
//               kinematics; returns how far a legless body bent by its wave must rise out of
//               the ground (limb_clearance.h), which body placement applies (raise_body) and
//               lift_pose follows;
//   pose_limbs  the tail kept out of steps, every leg by the leg IK job (leg_ik.h), arms
//               swinging and kept above the ground, fins beating and kept clear, folded wings
//               kept clear, and the matrices of the limb bones nothing else placed.
// Owns PoseState: the pose, its matrices and the tail's spring. The legs' joint angles, the
// matrices of the bones no stage reads (ribs, neck, skull, tail...) and the world matrices are
// worked out on first use after a tick (pose_angles, facing_matrices, world_matrices), so
// headless simulation and ticks between rendered frames do not pay for them.

#include <array>
#include <vector>

#include <glm/vec2.hpp>

#include "ossa/anim/anim_state.h"
#include "ossa/anim/gait_clock.h"
#include "ossa/anim/pentapedal.h"
#include "ossa/anim/secondary_motion.h"
#include "ossa/anim/spline_prototypes.h"
#include "ossa/skeleton/pose.h"

namespace ossa::anim {

struct PoseState {
  mutable Pose pose;                               // (the legs' angles are filled in lazily)
  TailSpring tail;
  std::vector<std::array<glm::vec2, 3>> leg_dirs;  // per leg: upper, lower, foot directions (_fs)
  float flex_step = 0.0f;                          // each flexing spine bone's turn (AnimRig::flex_sign), radians
  PentapedalState pentapedal;                      // the hands' places in the pentapedal walk
  bool drape_met_level = false;                    // a box lay over a bone of the legless drape
  // Caches of the lazily computed outputs.
  mutable std::vector<Mat2x3> facing;              // facing-space matrices (_fs)
  mutable std::vector<Mat2x3> world;               // world matrices (_ws)
  mutable bool leg_angles_dirty = false;
  mutable bool facing_dirty = true;                // bones outside rig.tick_bone are stale
  mutable bool world_dirty = true;
};

// The rest pose and matrices of `rig` (a new animator).
void init_pose(const AnimRig& rig, PoseState& state);

// The head's motion this tick (GaitState::head_rise, head_shift; trunk_bob.h), metres.
struct HeadMotion {
  float rise = 0.0f, shift = 0.0f;
};

// The body's joints and forward kinematics (above). `root_vy`: the root's vertical speed (m/s,
// body placement's), `crawl_phase` the legless wave's (cycles), `speed` m/s; `head` turns the
// neck about its base (AnimRig::nod_bone) so the skull's far end moves by about that much,
// the head kept level (a bird's head-bob) or following half the nod. Returns the rise a
// legless body needs (metres, 0 for any other).
float pose_body(const AnimContext& ctx, const BodyFrame& body, float root_vy, float crawl_phase, float speed, float dt,
                PoseState& state, HeadMotion head = {});
// The body rose by `raise` metres after pose_body (body placement's raise_body): the pose
// follows.
void lift_pose(const AnimRig& rig, float raise, PoseState& state);
// The limbs (above). `motion` in [0, 1] is the speed as a fraction of the walk speed; `dt` the
// tick's seconds (0: the same tick posed again), over which the tail's held turn settles.
void pose_limbs(const AnimContext& ctx, const SplinePrototypes& prototypes, const BodyFrame& body, const FootSet& feet,
                const GaitState& gait, float motion, float dt, PoseState& state);

// The lazily computed outputs (see above).
const Pose& pose_angles(const AnimRig& rig, const PoseState& state);
const std::vector<Mat2x3>& facing_matrices(const AnimRig& rig, const PoseState& state);
const std::vector<Mat2x3>& world_matrices(const AnimRig& rig, const BodyFrame& body, const PoseState& state);
// Facing space → world: a mirror of x by the facing and the root's world x.
Mat2x3 facing_to_world(const BodyFrame& body);

}  // namespace ossa::anim
