#include "ossa/anim/pose_stage.h"

#include <algorithm>
#include <cmath>

#include "ossa/anim/anim_math.h"
#include "ossa/anim/leg_ik.h"
#include "ossa/anim/limb_clearance.h"
#include "ossa/math/angle.h"

namespace ossa::anim {

namespace {

// The body's forward kinematics: the root, then each girdle straight from it (or the chains to
// the girdles when the spine bends).
void body_fk(const AnimRig& rig, PoseState& state) {
  const std::vector<int>& parents = rig.skeleton.parents();
  std::vector<Mat2x3>& model = state.facing;
  for (int b : rig.needed_bones) {
    const Mat2x3 local = rig.dynamic_bone[b] ? local_matrix(state.pose.locals[b]) : rig.rest_local_m[b];
    model[b] = parents[b] < 0 ? local : model[parents[b]] * local;
  }
  const Mat2x3 root = model[rig.root];
  for (size_t i = 0; i < rig.girdle_bones.size(); ++i) model[rig.girdle_bones[i]] = root * rig.girdle_rel[i];
}

}  // namespace

void init_pose(const AnimRig& rig, PoseState& state) {
  state.pose = rig.rest_pose;
  state.facing = rig.model_rest;
  state.leg_dirs.resize(rig.legs.size());
}

float pose_body(const AnimContext& ctx, const BodyFrame& body, float root_vy, float crawl_phase, float speed, float dt,
                PoseState& state) {
  const AnimRig& rig = ctx.rig;
  Pose& pose = state.pose;
  for (int b : rig.touched_bones) pose.locals[b] = rig.rest_pose.locals[b];
  const float body_angle = body.pitch + body.lean;
  pose.locals[rig.root].offset_ls = {0.0f, body.root_y_ws};
  pose.locals[rig.root].angle_ls += body_angle;
  if (rig.skull >= 0) pose.locals[rig.skull].angle_ls -= body_angle;  // the head stays level
  swing_tail(rig, ctx.params, dt, root_vy, body_angle, state.tail, pose);
  crawl_wave(rig, ctx.params, crawl_phase, speed, pose);
  // Forward kinematics in two passes: the body first, then the limb chains after IK.
  state.facing.resize(rig.skeleton.bone_count());
  body_fk(rig, state);
  if (!rig.legs.empty()) return 0.0f;
  return std::max(body_out_of_ground(ctx, body, state.facing, pose), 0.0f);
}

void lift_pose(const AnimRig& rig, float raise, PoseState& state) {
  state.pose.locals[rig.root].offset_ls.y += raise;
  body_fk(rig, state);
}

void pose_limbs(const AnimContext& ctx, const SplinePrototypes& prototypes, const BodyFrame& body, const FootSet& feet,
                const GaitState& gait, float motion, PoseState& state) {
  const AnimRig& rig = ctx.rig;
  Pose& pose = state.pose;
  std::vector<Mat2x3>& model = state.facing;
  if (rig.tail_length > 0.0f) keep_tail_clear(ctx, body, model, pose);
  const LegIkJob ik{&ctx, &body, &feet, &pose, &model, &state.leg_dirs, gait.moving};
  ik.run();
  // Arms swing counter to the same-side leg; fins trail with a slow beat; wings stay folded.
  for (const RigLimb& arm : rig.arms) {
    swing_arm(rig, prototypes, gait, feet, arm, motion, pose);
    keep_arm_above_ground(ctx, body, arm, model, pose);
  }
  for (const RigLimb& fin : rig.fins) {
    beat_fin(ctx.params, fin, motion, gait.crawl_phase + gait.phase, pose);
    keep_fin_clear(ctx, body, fin, model, pose);
  }
  for (const RigLimb& wing : rig.wings) keep_fin_clear(ctx, body, wing, model, pose);
  const std::vector<int>& parents = rig.skeleton.parents();
  for (int b : rig.other_limb_bones) model[b] = model[parents[b]] * local_matrix(pose.locals[b]);
  state.world_dirty = true;
  state.facing_dirty = true;
  state.leg_angles_dirty = true;
}

const Pose& pose_angles(const AnimRig& rig, const PoseState& state) {
  if (state.leg_angles_dirty) {
    // The legs' joint angles from the directions the leg IK left (the matrices need none).
    Pose& pose = state.pose;
    for (size_t i = 0; i < rig.legs.size(); ++i) {
      const RigLeg& info = rig.legs[i];
      const auto& [upper_dir, lower_dir, foot_dir] = state.leg_dirs[i];
      const float girdle = std::isnan(info.girdle_rel_angle) ? bone_angle(state.facing[info.girdle_bone])
                                                              : pose.locals[rig.root].angle_ls + info.girdle_rel_angle;
      const float upper = fast_atan2(upper_dir.y, upper_dir.x);
      const float lower = fast_atan2(upper_dir.x * lower_dir.y - upper_dir.y * lower_dir.x, glm::dot(upper_dir, lower_dir));
      const float foot = foot_dir == info.foot_dir_ms ? info.foot_angle_ms : fast_atan2(foot_dir.y, foot_dir.x);
      pose.locals[info.bones[0]].angle_ls = wrap_angle(upper - girdle);
      pose.locals[info.bones[1]].angle_ls = lower;
      pose.locals[info.bones[2]].angle_ls = wrap_angle(foot - (upper + lower));
    }
    state.leg_angles_dirty = false;
  }
  return state.pose;
}

const std::vector<Mat2x3>& facing_matrices(const AnimRig& rig, const PoseState& state) {
  if (state.facing_dirty) {
    const std::vector<int>& parents = rig.skeleton.parents();
    std::vector<Mat2x3>& model = state.facing;
    for (int b = 0; b < rig.skeleton.bone_count(); ++b) {
      if (rig.tick_bone[b]) continue;
      const Mat2x3 local = rig.dynamic_bone[b] ? local_matrix(state.pose.locals[b]) : rig.rest_local_m[b];
      model[b] = parents[b] < 0 ? local : model[parents[b]] * local;
    }
    state.facing_dirty = false;
  }
  return state.facing;
}

Mat2x3 facing_to_world(const BodyFrame& body) {
  Mat2x3 m;
  m.m[0] = static_cast<float>(body.facing);
  m.m[4] = body.x_ws;
  return m;
}

const std::vector<Mat2x3>& world_matrices(const AnimRig& rig, const BodyFrame& body, const PoseState& state) {
  const std::vector<Mat2x3>& facing = facing_matrices(rig, state);
  if (state.world_dirty) {
    state.world.resize(facing.size());
    const Mat2x3 m = facing_to_world(body);
    for (size_t i = 0; i < facing.size(); ++i) state.world[i] = m * facing[i];
    state.world_dirty = false;
  }
  return state.world;
}

}  // namespace ossa::anim
