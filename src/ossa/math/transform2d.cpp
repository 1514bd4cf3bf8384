#include "ossa/math/transform2d.h"

#include "ossa/assert.h"
#include "ossa/math/angle.h"

#include <cmath>

namespace ossa {

namespace {

glm::vec2 rotate(glm::vec2 v, float c, float s) { return {c * v.x - s * v.y, s * v.x + c * v.y}; }

}  // namespace

glm::mat3 Mat2x3::to_glm() const {
  return glm::mat3(m[0], m[1], 0.0f, m[2], m[3], 0.0f, m[4], m[5], 1.0f);
}

glm::vec2 Transform2D::apply_vector(glm::vec2 v) const {
  if (mirror_x) v.x = -v.x;
  return scale * rotate(v, std::cos(rotation), std::sin(rotation));
}

glm::vec2 Transform2D::apply_point(glm::vec2 p) const { return translation + apply_vector(p); }

Transform2D Transform2D::inverse() const {
  OSSA_ASSERT(scale != 0.0f, "Transform2D::inverse: scale is zero");
  // p = Mx R(-θ) (p' - T) / s, and Mx R(-θ) = R(θ) Mx: a mirrored transform keeps its angle.
  Transform2D inv;
  inv.scale = 1.0f / scale;
  inv.mirror_x = mirror_x;
  inv.rotation = mirror_x ? rotation : -rotation;
  inv.translation = -inv.apply_vector(translation);
  return inv;
}

Mat2x3 Transform2D::to_mat2x3() const {
  const float c = scale * std::cos(rotation);
  const float s = scale * std::sin(rotation);
  const float mx = mirror_x ? -1.0f : 1.0f;
  Mat2x3 r;
  r.m[0] = mx * c;  // image of the x axis: R (±1, 0)
  r.m[1] = mx * s;
  r.m[2] = -s;  // image of the y axis: R (0, 1)
  r.m[3] = c;
  r.m[4] = translation.x;
  r.m[5] = translation.y;
  return r;
}

Transform2D compose(const Transform2D& a, const Transform2D& b) {
  // a(b(p)) = Ta + sa Ra Ma (Tb + sb Rb Mb p); Ma Rb = R(-θb) Ma, so the linear part is
  // sa sb R(θa ± θb) Ma Mb.
  Transform2D r;
  r.translation = a.apply_point(b.translation);
  r.rotation = wrap_angle(a.rotation + (a.mirror_x ? -b.rotation : b.rotation));
  r.scale = a.scale * b.scale;
  r.mirror_x = a.mirror_x != b.mirror_x;
  return r;
}

}  // namespace ossa
