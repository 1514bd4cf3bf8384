#include "ossa/skeleton/mid_joint.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "ossa/assert.h"

namespace ossa {

namespace {

// The unit complex square root of the unit complex z, the shorter way: normalise(1 + z)
// (a half turn gives a quarter turn).
glm::vec2 unit_sqrt(glm::vec2 z) {
  const glm::vec2 h(1.0f + z.x, z.y);
  const float len = glm::length(h);
  return len > 1e-6f * (1.0f + glm::length(z)) ? h / len : glm::vec2(0.0f, 1.0f);
}

}  // namespace

namespace {

// The child's turn relative to the parent: L_p⁻¹ L_c is a rotation (any common scale or
// mirror cancels), the unit complex z.
glm::vec2 relative_turn(const Mat2x3& parent, const Mat2x3& child) {
  const float a = parent.m[0], b = parent.m[1], c = parent.m[2], d = parent.m[3];
  const float det = a * d - b * c;
  glm::vec2 z(1.0f, 0.0f);
  if (std::fabs(det) > 1e-20f) {
    z = glm::vec2(d * child.m[0] - c * child.m[1], -b * child.m[0] + a * child.m[1]) / det;
    z /= std::max(glm::length(z), 1e-20f);
  }
  return z;
}

}  // namespace

glm::vec2 mid_joint_half_turn(const Mat2x3& parent, const Mat2x3& child) { return unit_sqrt(relative_turn(parent, child)); }

Mat2x3 mid_joint_frame(const Mat2x3& parent, const Mat2x3& child, float turn, glm::vec2 near_half) {
  // Its quarters are square roots, no trigonometry. The half turn is the one nearer
  // `near_half` (the bind pose's): a joint folded past a half turn from there keeps turning
  // the same way instead of flipping to the shorter way round.
  glm::vec2 half = unit_sqrt(relative_turn(parent, child));
  if (glm::dot(half, near_half) < 0.0f) half = -half;
  glm::vec2 r = half;
  if (turn < 0.375f) {
    r = unit_sqrt(half);  // a quarter
  } else if (turn > 0.625f) {
    const glm::vec2 q = unit_sqrt(half);
    r = glm::vec2(half.x * q.x - half.y * q.y, half.x * q.y + half.y * q.x);  // three quarters
  }
  Mat2x3 turn_m;
  turn_m.m[0] = r.x, turn_m.m[1] = r.y, turn_m.m[2] = -r.y, turn_m.m[3] = r.x;
  Mat2x3 mid = parent * turn_m;
  mid.m[4] = child.m[4];
  mid.m[5] = child.m[5];
  return mid;
}

Mat2x3 level_frame(const MidJoint& j, const Mat2x3& child) {
  // The creature's mirror and scale: a rest pose has neither, so the world matrix's
  // determinant is the model-to-world transform's.
  const float det = child.m[0] * child.m[3] - child.m[1] * child.m[2];
  const float scale = std::sqrt(std::fabs(det));
  const float mirror = det < 0.0f ? -1.0f : 1.0f;
  // The bone's turn since the rest pose: the frame stays level through kLevelTurn of it and
  // turns with the bone beyond (a hoof swung forward with its cannon bone, not bent flat
  // against it).
  // (No trigonometry: beyond the limit the frame is the bone's axis turned back by it.)
  glm::vec2 x = j.rest_x;
  if (scale > 0.0f) {
    const glm::vec2 now(mirror * child.m[0] / scale, child.m[1] / scale);
    if (glm::dot(j.rest_x, now) < kCosLevelTurn) {
      const float s = (j.rest_x.x * now.y - j.rest_x.y * now.x) < 0.0f ? -kSinLevelTurn : kSinLevelTurn;
      x = {kCosLevelTurn * now.x + s * now.y, kCosLevelTurn * now.y - s * now.x};
    }
  }
  Mat2x3 f;
  f.m[0] = mirror * scale * x.x;
  f.m[1] = scale * x.y;
  f.m[2] = mirror * scale * -x.y;
  f.m[3] = scale * x.x;
  const glm::vec2 at = child.apply(j.point_ls);
  f.m[4] = at.x;
  f.m[5] = at.y;
  return f;
}

void mid_joint_palette(std::span<const MidJoint> mid_joints, std::span<const Mat2x3> world,
                       std::span<Mat2x3> palette) {
  const size_t bones = world.size();
  OSSA_ASSERT(palette.size() == bones + mid_joints.size(), "mid_joint_palette: one entry per bone and mid joint");
  for (size_t i = 0; i < mid_joints.size(); ++i) {
    const MidJoint& j = mid_joints[i];
    const Mat2x3 frame = j.level ? level_frame(j, world[static_cast<size_t>(j.child)])
                                 : mid_joint_frame(world[static_cast<size_t>(j.parent)], world[static_cast<size_t>(j.child)], j.turn, j.rest_half);
    palette[bones + i] = frame * j.inverse_bind;
  }
}

}  // namespace ossa
