#pragma once
// Transform2D — a 2D similarity transform with an optional mirror, the transform of every bone
// and of a creature in the world (a creature facing left is the x-mirror of one facing right,
// DESIGN.md §3), and Mat2x3, its matrix form for bone palettes and the GPU.

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>

namespace ossa {

/// A 2D affine matrix stored as six floats, column-major:
///   | m[0] m[2] m[4] |      x' = m[0] x + m[2] y + m[4]
///   | m[1] m[3] m[5] |      y' = m[1] x + m[3] y + m[5]
/// (m[0], m[1]) and (m[2], m[3]) are the images of the x and y axes, (m[4], m[5]) the
/// translation — the first two columns of a glm::mat3 / GLSL mat3 in the same order.
struct Mat2x3 {
  float m[6] = {1.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f};

  static Mat2x3 identity() { return {}; }
  /// The point p transformed (linear part and translation).
  glm::vec2 apply(glm::vec2 p) const {
    return {m[0] * p.x + m[2] * p.y + m[4], m[1] * p.x + m[3] * p.y + m[5]};
  }
  /// The vector v transformed (linear part only).
  glm::vec2 apply_vector(glm::vec2 v) const {
    return {m[0] * v.x + m[2] * v.y, m[1] * v.x + m[3] * v.y};
  }
  /// The same matrix as a glm::mat3 with (0, 0, 1) as the last row.
  glm::mat3 to_glm() const;
};

/// a * b applies b first, then a (like matrices acting on column vectors). Inline: forward
/// kinematics and palettes do one per bone per tick.
inline Mat2x3 operator*(const Mat2x3& a, const Mat2x3& b) {
  Mat2x3 r;
  r.m[0] = a.m[0] * b.m[0] + a.m[2] * b.m[1];
  r.m[1] = a.m[1] * b.m[0] + a.m[3] * b.m[1];
  r.m[2] = a.m[0] * b.m[2] + a.m[2] * b.m[3];
  r.m[3] = a.m[1] * b.m[2] + a.m[3] * b.m[3];
  r.m[4] = a.m[0] * b.m[4] + a.m[2] * b.m[5] + a.m[4];
  r.m[5] = a.m[1] * b.m[4] + a.m[3] * b.m[5] + a.m[5];
  return r;
}

/// p ↦ translation + scale · R(rotation) · Mx(p), where Mx negates x when mirror_x is set.
/// Mirror is applied first, in the local frame, so a mirrored bone chain bends the other way
/// while its root stays put.
struct Transform2D {
  glm::vec2 translation{0.0f, 0.0f};  // in the parent / target frame (metres for the world)
  float rotation = 0.0f;              // radians, counter-clockwise
  float scale = 1.0f;                 // uniform; must be != 0 for inverse() (usually > 0)
  bool mirror_x = false;              // negate local x before rotating

  static Transform2D identity() { return {}; }

  glm::vec2 apply_point(glm::vec2 p) const;
  /// Directions and offsets: no translation.
  glm::vec2 apply_vector(glm::vec2 v) const;

  /// The inverse transform (asserts scale != 0): inverse().apply_point(apply_point(p)) == p.
  Transform2D inverse() const;

  /// The same transform as a matrix.
  Mat2x3 to_mat2x3() const;
};

/// a ∘ b: apply b first, then a. compose(a, b).apply_point(p) == a.apply_point(b.apply_point(p)).
/// The resulting rotation is wrapped to [-π, π].
Transform2D compose(const Transform2D& a, const Transform2D& b);

}  // namespace ossa
