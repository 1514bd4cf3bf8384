#pragma once
// Pose — one creature's animated joint values — and the jobs that turn it into matrices:
// forward kinematics (local joints → model-space and world-space bone matrices) and the
// skinning palette. Jobs follow STYLE.md (ozz IKTwoBoneJob style): documented input fields,
// outputs passed in, validate() / run(), no allocation inside run().

#include <cmath>
#include <span>
#include <vector>

#include "ossa/math/transform2d.h"
#include "ossa/skeleton/skeleton.h"

namespace ossa {

// The matrix of one joint: T(offset) · R(angle), bone frame → parent frame.
inline Mat2x3 local_matrix(const BoneLocal& l) {
  const float c = std::cos(l.angle_ls), s = std::sin(l.angle_ls);
  Mat2x3 m;
  m.m[0] = c;
  m.m[1] = s;
  m.m[2] = -s;
  m.m[3] = c;
  m.m[4] = l.offset_ls.x;
  m.m[5] = l.offset_ls.y;
  return m;
}

// The matrix of a bone frame whose x axis points along the unit vector dir, at origin (what
// local_matrix gives for an angle, here for a direction an IK solve already has).
inline Mat2x3 frame_matrix(glm::vec2 dir, glm::vec2 origin) {
  Mat2x3 m;
  m.m[0] = dir.x;
  m.m[1] = dir.y;
  m.m[2] = -dir.y;
  m.m[3] = dir.x;
  m.m[4] = origin.x;
  m.m[5] = origin.y;
  return m;
}

// Per-creature joint values, one BoneLocal per bone of its Skeleton.
struct Pose {
  std::vector<BoneLocal> locals;

  // The skeleton's rest pose.
  static Pose rest(const Skeleton& skeleton) { return Pose{skeleton.rest_locals()}; }
};

// Forward kinematics: model_i = model_parent(i) · T(offset_i) · R(angle_i), and optionally
// world_i = root_to_world · model_i. Because parents precede children, one pass suffices.
struct ForwardKinematicsJob {
  const Skeleton* skeleton = nullptr;     // input
  std::span<const BoneLocal> locals;      // input: one per bone
  Mat2x3 model_to_world;                  // input: creature placement (mirror for facing -x)
  std::span<Mat2x3> model;                // output: bone frame → model space, one per bone
  std::span<Mat2x3> world;                // optional output: bone frame → world space

  bool validate() const;
  bool run() const;
};

// The world-space joint positions of a pose: start (joint with parent) and end of each bone.
inline glm::vec2 bone_start(const Mat2x3& b) { return {b.m[4], b.m[5]}; }
inline glm::vec2 bone_end(const Mat2x3& b, float length) { return b.apply({length, 0.0f}); }

// Skinning palette: palette_i = world_i · inverse_bind_i, where inverse_bind maps a vertex from
// the space it was authored in (model space of the bind pose) to the bone frame. Sprite meshes
// authored directly in bone space pass an empty inverse_bind (palette = world).
struct PaletteJob {
  std::span<const Mat2x3> world;          // input
  std::span<const Mat2x3> inverse_bind;   // input, empty or one per bone
  std::span<Mat2x3> palette;              // output

  bool validate() const;
  bool run() const;
};

// Convenience: model-space matrices of a pose (allocates; for tools and tests).
std::vector<Mat2x3> model_matrices(const Skeleton& skeleton, std::span<const BoneLocal> locals);

// Inverse of an invertible affine matrix.
Mat2x3 inverse(const Mat2x3& m);

}  // namespace ossa
