#include "ossa/anim/animator.h"

// Stage 9 of the animator (DESIGN.md §7): the pose and forward kinematics — the joint values
// and the facing-space matrices the leg IK, the limb keep-outs and the renderer read, and the
// lazily computed outputs (joint angles of the legs, the rest of the skeleton's matrices, world
// matrices). The stages before it live in their own files; animator.cpp orders them.

#include <cmath>

#include "ossa/anim/anim_math.h"
#include "ossa/anim/leg_ik.h"
#include "ossa/anim/limb_clearance.h"
#include "ossa/math/angle.h"

namespace ossa {

using namespace anim;

// ---- Output ---------------------------------------------------------------------------------

const Pose& Animator::pose() const {
  if (leg_angles_dirty_) {
    // The legs' joint angles from the directions the leg IK left (the matrices need none).
    const AnimRig& rig = *rig_;
    for (size_t i = 0; i < rig.legs.size(); ++i) {
      const RigLeg& info = rig.legs[i];
      const auto& [upper_dir, lower_dir, foot_dir] = leg_dirs_[i];
      const float girdle = std::isnan(info.girdle_rel_angle) ? bone_angle(model_[info.girdle_bone])
                                                              : pose_.locals[rig.root].angle_ls + info.girdle_rel_angle;
      const float upper = fast_atan2(upper_dir.y, upper_dir.x);
      const float lower = fast_atan2(upper_dir.x * lower_dir.y - upper_dir.y * lower_dir.x, glm::dot(upper_dir, lower_dir));
      const float foot = foot_dir == info.foot_dir_ms ? info.foot_angle_ms : fast_atan2(foot_dir.y, foot_dir.x);
      pose_.locals[info.bones[0]].angle_ls = wrap_angle(upper - girdle);
      pose_.locals[info.bones[1]].angle_ls = lower;
      pose_.locals[info.bones[2]].angle_ls = wrap_angle(foot - (upper + lower));
    }
    leg_angles_dirty_ = false;
  }
  return pose_;
}

Mat2x3 Animator::model_to_world() const {
  Mat2x3 m;
  m.m[0] = static_cast<float>(body_.facing);
  m.m[4] = body_.x_ws;
  return m;
}

glm::vec2 Animator::foot_ws(int leg) const {
  const int b = rig_->legs[leg].contact_bone;
  return body_.to_ws(bone_end(model_[b], rig_->skeleton.length(b)));
}

const std::vector<Mat2x3>& Animator::model_matrices() const {
  if (model_dirty_) {
    const AnimRig& rig = *rig_;
    const std::vector<int>& parents = rig.skeleton.parents();
    for (int b = 0; b < rig.skeleton.bone_count(); ++b) {
      if (rig.tick_bone[b]) continue;
      const Mat2x3 local = rig.dynamic_bone[b] ? local_matrix(pose_.locals[b]) : rig.rest_local_m[b];
      model_[b] = parents[b] < 0 ? local : model_[parents[b]] * local;
    }
    model_dirty_ = false;
  }
  return model_;
}

const std::vector<Mat2x3>& Animator::world_matrices() const {
  model_matrices();
  if (world_dirty_) {
    world_.resize(model_.size());
    const Mat2x3 m = model_to_world();
    for (size_t i = 0; i < model_.size(); ++i) world_[i] = m * model_[i];
    world_dirty_ = false;
  }
  return world_;
}

// ---- Pose and forward kinematics --------------------------------------------------------

void Animator::body_fk() {
  const AnimRig& rig = *rig_;
  const std::vector<int>& parents = rig.skeleton.parents();
  for (int b : rig.needed_bones) {
    const Mat2x3 local = rig.dynamic_bone[b] ? local_matrix(pose_.locals[b]) : rig.rest_local_m[b];
    model_[b] = parents[b] < 0 ? local : model_[parents[b]] * local;
  }
  const Mat2x3 root = model_[rig.root];
  for (size_t i = 0; i < rig.girdle_bones.size(); ++i) model_[rig.girdle_bones[i]] = root * rig.girdle_rel[i];
}

void Animator::build_pose(float dt, const Level& level) {
  const AnimRig& rig = *rig_;
  const AnimContext ctx = context(level);
  for (int b : rig.touched_bones) pose_.locals[b] = rig.rest_pose.locals[b];
  const float body_angle = body_.pitch + body_.lean;
  pose_.locals[rig.root].offset_ls = {0.0f, body_.root_y_ws};
  pose_.locals[rig.root].angle_ls += body_angle;
  if (rig.skull >= 0) pose_.locals[rig.skull].angle_ls -= body_angle;  // the head stays level
  swing_tail(rig, params_, dt, body_state_.root_vy, body_angle, tail_, pose_);
  crawl_wave(rig, params_, crawl_phase_, speed_, pose_);
  // Forward kinematics in two passes: the body first (the root, then each girdle straight from
  // it, or the chains to the girdles when the spine bends), then the limb chains after IK.
  model_.resize(rig.skeleton.bone_count());
  body_fk();
  if (rig.legs.empty()) {
    const float raise = body_out_of_ground(ctx, body_, model_, pose_);
    if (raise > 0.0f) {
      body_.root_y_ws += raise;
      body_state_.body_lift += raise;
      pose_.locals[rig.root].offset_ls.y += raise;
      body_fk();
    }
  }
  if (rig.tail_length > 0.0f) keep_tail_clear(ctx, body_, model_, pose_);
  const LegIkJob ik{&ctx, &body_, &feet_, &pose_, &model_, &leg_dirs_};
  ik.run();
  // Arms swing counter to the same-side leg; fins trail with a slow beat; wings stay folded.
  const float motion = std::min(speed_ / std::max(walk_speed(), 1e-3f), 1.0f);
  for (const RigLimb& arm : rig.arms) {
    swing_arm(rig, spline_prototypes_, gait_, feet_, arm, motion, pose_);
    keep_arm_above_ground(ctx, body_, arm, model_, pose_);
  }
  for (const RigLimb& fin : rig.fins) {
    beat_fin(params_, fin, motion, crawl_phase_ + gait_.phase, pose_);
    keep_fin_clear(ctx, body_, fin, model_, pose_);
  }
  for (const RigLimb& wing : rig.wings) keep_fin_clear(ctx, body_, wing, model_, pose_);
  const std::vector<int>& parents = rig.skeleton.parents();
  for (int b : rig.other_limb_bones) model_[b] = model_[parents[b]] * local_matrix(pose_.locals[b]);
  world_dirty_ = true;
  model_dirty_ = true;
  leg_angles_dirty_ = true;
}

}  // namespace ossa
