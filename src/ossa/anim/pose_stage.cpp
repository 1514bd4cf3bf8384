#include "ossa/anim/pose_stage.h"

#include <algorithm>
#include <cmath>

#include "ossa/anim/anim_math.h"
#include "ossa/anim/leg_ik.h"
#include "ossa/anim/limb_clearance.h"
#include "ossa/anim/secondary_motion.h"
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
  if (state.flex_step != 0.0f) {
    for (size_t i = 0; i < rig.girdle_bones.size(); ++i) model[rig.girdle_bones[i]] = root * rig.flexed_girdle_rel(i, state.flex_step);
    return;
  }
  for (size_t i = 0; i < rig.girdle_bones.size(); ++i) model[rig.girdle_bones[i]] = root * rig.girdle_rel[i];
}

// The spine's flexion (AnimRig::flex_sign): each bone of the chains to the girdles turns by
// an equal share of body.flex, the back an arc.
void flex_spine(const AnimRig& rig, float flex, PoseState& state) {
  const float step = rig.flex_count > 0 ? flex / static_cast<float>(rig.flex_count) : 0.0f;
  if (step == 0.0f && state.flex_step == 0.0f) return;
  for (const std::vector<int>& chain : rig.flex_chains) {
    for (int b : chain) state.pose.locals[b].angle_ls = rig.rest_pose.locals[b].angle_ls + static_cast<float>(rig.flex_sign[b]) * step;
  }
  if (rig.flex_neck >= 0) state.pose.locals[rig.flex_neck].angle_ls += rig.flex_neck_turn * step;
  state.flex_step = step;
}

// Bend the neck at its two nod joints so that the skull's joint (and, the head kept level, its
// far end) moves by (shift, rise): the neck from its base to the second joint and from there
// to the head taken as two bones, solved exactly (law of cosines), bent to the side it is bent
// at rest (a straight neck: the side that moves the middle forward, away from the body). A one-
// bone neck turns about its base by the angle that best moves the head. The head follows half
// the nod.
void pose_head(const AnimRig& rig, HeadMotion head, Pose& pose) {
  const glm::vec2 d{head.shift, head.rise};
  const glm::vec2 r0 = rig.nod_reach[0];
  float turn0 = 0.0f, turn1 = 0.0f;
  if (rig.nod_bones[1] < 0) {
    turn0 = (r0.x * d.y - r0.y * d.x) / std::max(glm::dot(r0, r0), 1e-8f);
  } else {
    const glm::vec2 lower = r0 - rig.nod_reach[1], upper = rig.nod_reach[1];
    const float a = glm::length(lower), b = glm::length(upper);
    const glm::vec2 target = r0 + d;
    const float c = std::clamp(glm::length(target), std::fabs(a - b) + 1e-4f, a + b - 1e-4f);
    if (!(a > 0.0f && b > 0.0f && c > 0.0f)) return;
    const float alpha = std::acos(std::clamp((a * a + c * c - b * b) / (2.0f * a * c), -1.0f, 1.0f));
    const float aim = std::atan2(target.y, target.x);
    const float across = r0.x * lower.y - r0.y * lower.x;  // > 0: the middle lies left of base → head
    float side = across > 0.0f ? 1.0f : -1.0f;
    if (std::fabs(across) < 1e-3f * glm::dot(r0, r0)) side = std::cos(aim + alpha) > std::cos(aim - alpha) ? 1.0f : -1.0f;
    const float lower_angle = aim + side * alpha;
    const glm::vec2 lower_now = a * glm::vec2(std::cos(lower_angle), std::sin(lower_angle));
    turn0 = wrap_angle(lower_angle - std::atan2(lower.y, lower.x));
    const glm::vec2 upper_now = target - lower_now;
    turn1 = wrap_angle(std::atan2(upper_now.y, upper_now.x) - std::atan2(upper.y, upper.x) - turn0);
  }
  constexpr float kMaxBend = 0.8f;  // radians at each joint
  turn0 = std::clamp(turn0, -kMaxBend, kMaxBend);
  turn1 = std::clamp(turn1, -kMaxBend, kMaxBend);
  pose.locals[rig.nod_bones[0]].angle_ls += turn0;
  if (rig.nod_bones[1] >= 0) pose.locals[rig.nod_bones[1]].angle_ls += turn1;
  const float follow = 0.5f * head.rise / std::max(glm::length(r0), 1e-4f);
  pose.locals[rig.skull].angle_ls += follow - turn0 - turn1;
}

}  // namespace

void init_pose(const AnimRig& rig, PoseState& state) {
  state.pose = rig.rest_pose;
  state.facing = rig.model_rest;
  state.leg_dirs.resize(rig.legs.size());
}

float pose_body(const AnimContext& ctx, const BodyFrame& body, float root_vy, float crawl_phase, float speed, float dt,
                PoseState& state, HeadMotion head) {
  const AnimRig& rig = ctx.rig;
  Pose& pose = state.pose;
  for (int b : rig.touched_bones) pose.locals[b] = rig.rest_pose.locals[b];
  const float body_angle = body.pitch + body.lean;
  pose.locals[rig.root].offset_ls = {0.0f, body.root_y_ws};
  pose.locals[rig.root].angle_ls += body_angle;
  if (rig.skull >= 0) pose.locals[rig.skull].angle_ls -= body_angle;  // the head stays level
  if (rig.nod_bones[0] >= 0 && (head.rise != 0.0f || head.shift != 0.0f)) pose_head(rig, head, pose);
  flex_spine(rig, body.flex, state);
  swing_tail(rig, ctx.params, dt, root_vy, body_angle, state.tail, pose);
  // Forward kinematics in two passes: the body first, then the limb chains after IK.
  state.facing.resize(rig.skeleton.bone_count());
  if (!rig.legs.empty()) {
    body_fk(rig, state);
    return 0.0f;
  }
  state.drape_met_level = drape_legless(ctx, body, crawl_phase, speed, pose, state.facing);
  return std::max(body_out_of_ground(ctx, body, state.facing, pose), 0.0f);
}

void lift_pose(const AnimRig& rig, float raise, PoseState& state) {
  state.pose.locals[rig.root].offset_ls.y += raise;
  if (rig.legs.empty()) {  // the bones the drape placed rise (the rest follow on demand)
    for (int b : rig.drape_fk) state.facing[b].m[5] += raise;
    return;
  }
  body_fk(rig, state);
}

void pose_limbs(const AnimContext& ctx, const SplinePrototypes& prototypes, const BodyFrame& body, const FootSet& feet,
                const GaitState& gait, float motion, float dt, PoseState& state) {
  const AnimRig& rig = ctx.rig;
  Pose& pose = state.pose;
  std::vector<Mat2x3>& model = state.facing;
  press_tail(ctx, body, feet, gait, model, pose);
  if (rig.tail_length > 0.0f) keep_tail_clear(ctx, body, model, dt, state.tail, pose);
  if (rig.nod_bones[0] >= 0) keep_head_clear(ctx, body, model, pose);
  const LegIkJob ik{&ctx, &body, &feet, &pose, &model, &state.leg_dirs, gait.moving};
  ik.run();
  // Arms swing counter to the same-side leg (or stand on the ground in the pentapedal walk);
  // fins trail with a slow beat; wings stay folded.
  for (const RigLimb& arm : rig.arms) swing_arm(rig, prototypes, gait, feet, arm, motion, pose);
  plant_hands(ctx, body, feet, gait, model, state.pentapedal, pose);
  const float arm_margin = hand_margin(rig, gait);
  for (const RigLimb& arm : rig.arms) keep_arm_above_ground(ctx, body, arm, model, arm_margin, pose, !(gait.pentapedal > 0.0f));
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
      const float girdle = std::isnan(info.girdle_rel_angle) || state.flex_step != 0.0f ? bone_angle(state.facing[info.girdle_bone])
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
      const bool bent = rig.dynamic_bone[b] || (state.flex_step != 0.0f && rig.flex_sign[b] != 0);
      const Mat2x3 local = bent ? local_matrix(state.pose.locals[b]) : rig.rest_local_m[b];
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
