#pragma once
// Mid-joint frames: the skinning frames smooth skinning blends through across a limb joint
// (draw/sprite_mesh.h for bone sprites, body/body_mesh.h for bodies). A mid-joint frame sits
// at the child bone's start, its axes turned a quarter, half or three quarters of the way from
// the parent's axes to the child's; blending a vertex between neighbouring frames in turn
// never spans more than that step of the joint's turn, so a bent joint keeps its thickness
// (a linear blend of parent and child alone collapses toward the joint: the "candy wrapper").
// GL-free: computed on the CPU into the palette every frame.

#include <span>

#include <glm/vec2.hpp>

#include "ossa/math/transform2d.h"

namespace ossa {

// A mid-joint frame of smooth skinning: at the child's start, its axes turned `turn` of the
// way from the parent's to the child's (mid_joint_frame). It has a palette entry of its own
// after the bones' (index bone_count + i in the mesh's mid_joints), computed every frame
// from the two bones' world matrices (mid_joint_palette; CreatureBatch::set_world).
struct MidJoint {
  int parent = 0, child = 0;  // bones
  float turn = 0.5f;          // 0.25, 0.5 or 0.75
  Mat2x3 inverse_bind;        // model space → the mid frame of the bind pose
  // Half the joint's turn in the bind pose (mid_joint_half_turn): the frames turn from there
  // the way the joint does, even past a half turn (a foot folded up under its shin).
  glm::vec2 rest_half{1.0f, 0.0f};
  // A level frame instead (a foot's toes, hoof or claws, which stay flat on the ground while
  // the foot bone turns over them): at `point_ls` of bone `child` (its contact point, the
  // bone's end), turned as that bone is in the rest pose, `rest_x` (its unit x axis in model
  // space), while the bone turns up to kLevelTurn either way from it, and with the bone beyond
  // that; mirrored and scaled with the creature.
  bool level = false;
  glm::vec2 point_ls{0.0f};
  glm::vec2 rest_x{1.0f, 0.0f};
};

// How far (radians) a foot bone turns from its rest angle with its level frame held level
// (the roll of a hoof or toes over the ground); beyond it the frame turns along.
inline constexpr float kLevelTurn = 1.3f;
inline constexpr float kCosLevelTurn = 0.26749883f, kSinLevelTurn = 0.96355819f;  // of kLevelTurn

// The level frame of `j` (MidJoint::level) for the child bone's frame `child` (bone frame →
// world): at its contact point, with the child's rest turn, mirrored and scaled as `child`.
Mat2x3 level_frame(const MidJoint& j, const Mat2x3& child);

// The mid-joint frame of a parent and a child bone frame (bone frame → model or world): at
// the child's origin, turned from the parent's axes by `turn` (0.25, 0.5 or 0.75; others are
// rounded to these) of the child's turn relative to the parent (the shorter way). Any common
// scale or mirror of the two is kept: the frames of a creature facing left give the mirrored
// mid frame.
// `near_half`: of the two half turns, the one nearer this (the bind pose's, MidJoint::rest_half;
// the default picks the shorter way).
Mat2x3 mid_joint_frame(const Mat2x3& parent, const Mat2x3& child, float turn = 0.5f, glm::vec2 near_half = {1.0f, 0.0f});
// Half the child's turn relative to the parent, the shorter way, as a unit complex number.
glm::vec2 mid_joint_half_turn(const Mat2x3& parent, const Mat2x3& child);
// palette[bones + i] = mid_joint_frame(world[parent], world[child], turn) · inverse_bind (or
// level_frame(j, world[child]) · inverse_bind) for every mid joint; `palette` holds
// bone_count + mid_joints.size() entries, its bones' already set.
void mid_joint_palette(std::span<const MidJoint> mid_joints, std::span<const Mat2x3> world,
                       std::span<Mat2x3> palette);

}  // namespace ossa
