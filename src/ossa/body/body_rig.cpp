// The body builder's rig: the rest pose, the axial chain (snout tip → tail tip over the skull
// and every vertebra) and the skin of a point on a chain (body_parts.h).

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "ossa/body/body_parts.h"
#include "ossa/skeleton/pose.h"

namespace ossa::body {

int Chain::segment_at(float s) const {
  const int n = static_cast<int>(bones.size());
  if (n == 0) return -1;
  // Segments are few (≤ ~100): a binary search over start_s.
  const auto it = std::upper_bound(start_s.begin(), start_s.end(), s);
  const int k = static_cast<int>(it - start_s.begin()) - 1;
  return std::clamp(k, 0, n - 1);
}

glm::vec2 Chain::point_at(float s) const {
  const int k = segment_at(s);
  if (k < 0) return points.empty() ? glm::vec2(0.0f) : points.front();
  const float len = start_s[k + 1] - start_s[k];
  const float u = len > 0.0f ? std::clamp((s - start_s[k]) / len, 0.0f, 1.0f) : 0.0f;
  return points[k] + u * (points[k + 1] - points[k]);
}

glm::vec2 Chain::tangent_at(float s) const {
  const int k = segment_at(s);
  if (k < 0) return {1.0f, 0.0f};
  const glm::vec2 d = points[k + 1] - points[k];
  const float len = glm::length(d);
  return len > 0.0f ? d / len : glm::vec2(1.0f, 0.0f);
}

float Chain::nearest_s(glm::vec2 p) const {
  float best = 1e30f, best_s = 0.0f;
  for (size_t k = 0; k + 1 < points.size(); ++k) {
    const glm::vec2 a = points[k], d = points[k + 1] - a;
    const float len2 = glm::dot(d, d);
    const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, d) / len2, 0.0f, 1.0f) : 0.0f;
    const float dist = glm::length(a + t * d - p);
    if (dist < best) best = dist, best_s = start_s[k] + t * (start_s[k + 1] - start_s[k]);
  }
  return best_s;
}

glm::vec2 BodyRig::bone_end(int b) const {
  return rest[static_cast<size_t>(b)].apply({creature->skeleton.length(b), 0.0f});
}

glm::vec2 BodyRig::bone_dir(int b) const {
  const Mat2x3& m = rest[static_cast<size_t>(b)];
  const glm::vec2 x(m.m[0], m.m[1]);
  const float len = glm::length(x);
  return len > 0.0f ? x / len : glm::vec2(1.0f, 0.0f);
}

Skin chain_skin(const Chain& chain, const std::vector<JointBlend>& joints, float s) {
  // Within a joint's blend: its frames evenly over [-half_width, half_width], linear between
  // neighbours (so the joint's turn spreads along a circular arc, as the bone sprites do).
  for (const JointBlend& j : joints) {
    if (j.frames.size() < 2 || !(j.half_width > 0.0f) || std::fabs(s - j.s) >= j.half_width) continue;
    const int steps = static_cast<int>(j.frames.size()) - 1;
    const float x = std::clamp((s - j.s + j.half_width) / (2.0f * j.half_width), 0.0f, 1.0f) * static_cast<float>(steps);
    const int i = std::min(static_cast<int>(x), steps - 1);
    const float t = x - static_cast<float>(i);
    Skin skin;
    skin.index = {static_cast<uint8_t>(j.frames[static_cast<size_t>(i)]), static_cast<uint8_t>(j.frames[static_cast<size_t>(i + 1)])};
    skin.weight = {1.0f - t, t};
    return skin;
  }
  const int k = chain.segment_at(s);
  return Skin::rigid(k >= 0 ? chain.bones[static_cast<size_t>(k)] : 0);
}

BodyRig make_rig(const Creature& c) {
  BodyRig rig;
  rig.creature = &c;
  const Skeleton& sk = c.skeleton;
  rig.bone_count = sk.bone_count();
  const std::vector<BoneLocal>& locals =
      c.rest_pose.locals.size() == static_cast<size_t>(rig.bone_count) ? c.rest_pose.locals : sk.rest_locals();
  rig.rest = model_matrices(sk, locals);

  float back = 0.0f;
  for (int b : c.back) back += sk.length(b);
  rig.back_length = std::max(back, 1e-4f);

  // Head → tail. A headward bone (the skull, the neck, the front half of the back) is walked
  // from its end to its start; a tailward one (rear half, tail) from its start to its end.
  Chain& ch = rig.axial;
  const auto add = [&](int bone, bool headward) {
    if (bone < 0 || !(sk.length(bone) > 1e-6f) || !std::isfinite(sk.length(bone))) return;
    const glm::vec2 from = headward ? rig.bone_end(bone) : rig.bone_start(bone);
    const glm::vec2 to = headward ? rig.bone_start(bone) : rig.bone_end(bone);
    if (ch.points.empty()) ch.points.push_back(from);
    ch.points.push_back(to);
    ch.bones.push_back(bone);
  };
  if (c.skull >= 0) {
    add(c.skull, true);
    if (!ch.bones.empty()) rig.skull_segment = 0;
    rig.skull_length = sk.length(c.skull);
    rig.skull_height = sk.width(c.skull);
  }
  for (int b : c.neck) add(b, true);
  const size_t before_back = ch.bones.size();
  for (int b : c.back) add(b, !sk.sprite_flip_y(b));
  const size_t after_back = ch.bones.size();
  for (int b : c.tail) add(b, false);
  rig.snout = std::clamp(c.skull_snout, 0.05f, 0.95f);

  ch.start_s.assign(ch.points.size(), 0.0f);
  for (size_t i = 1; i < ch.points.size(); ++i) ch.start_s[i] = ch.start_s[i - 1] + glm::length(ch.points[i] - ch.points[i - 1]);
  const auto s_at = [&](size_t segment) { return segment < ch.start_s.size() ? ch.start_s[segment] : ch.length(); };
  rig.snout_s = rig.skull_segment == 0 ? s_at(1) : 0.0f;
  rig.shoulder_s = s_at(before_back);
  rig.hip_s = s_at(after_back);
  rig.tail_s = ch.length();

  // Spine joints blend their two vertebrae directly (they turn a few degrees each): over half
  // the shorter neighbour either side, so every section but the joints' own follows one bone.
  for (size_t k = 1; k < ch.bones.size(); ++k) {
    const float l0 = ch.start_s[k] - ch.start_s[k - 1], l1 = ch.start_s[k + 1] - ch.start_s[k];
    JointBlend j;
    j.s = ch.start_s[k];
    j.half_width = 0.5f * std::min(l0, l1);
    j.frames = {ch.bones[k - 1], ch.bones[k]};
    rig.axial_joints.push_back(j);
  }
  return rig;
}

}  // namespace ossa::body
