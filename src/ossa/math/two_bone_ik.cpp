#include "ossa/math/two_bone_ik.h"

#include "ossa/assert.h"
#include "ossa/math/angle.h"

#include <cmath>

namespace ossa {

namespace {

bool finite(glm::vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }

}  // namespace

bool TwoBoneIkJob::validate() const {
  return finite(root) && finite(target) && std::isfinite(upper_length) &&
         std::isfinite(lower_length) && upper_length >= 0.0f && lower_length >= 0.0f &&
         (bend_sign == 1.0f || bend_sign == -1.0f) && soft_reach >= 0.0f && soft_reach < 1.0f;
}

bool TwoBoneIkJob::run() {
  if (!validate()) return false;
  // The triangle is solved in double: the lower bone's direction is (r - x, h) / l2, and with
  // a short lower bone (foot-sized l2 under a long thigh) float rounding of x and h, relative
  // to l1, would be amplified by l1 / l2. Double also keeps the squares of millimetre and of
  // kilometre chains normal numbers. Scalar double costs about the same as float on x86-64.
  const double l1 = upper_length;
  const double l2 = lower_length;
  const double b = bend_sign;

  // Unit direction root → target; a target on the root points the chain along +x.
  const double dx = static_cast<double>(target.x) - root.x;
  const double dy = static_cast<double>(target.y) - root.y;
  const double dist = std::sqrt(dx * dx + dy * dy);
  double dir_x = 1.0, dir_y = 0.0;
  if (dist > 1e-300) {
    const double inv = 1.0 / dist;
    dir_x = dx * inv;
    dir_y = dy * inv;
  }

  // Effective distance r of the end from the root. Soft reach (as in "soft IK"): beyond
  // start = (1 - soft_reach) * reach the end approaches full reach exponentially,
  // r = start + soft (1 - e^(-(dist - start) / soft)): continuous with slope 1 at start, and
  // r <= dist because 1 - e^-y <= y, so the end never passes the target.
  const double max_reach = l1 + l2;
  const double min_reach = std::fabs(l1 - l2);
  double r = dist;
  if (soft_reach > 0.0f) {
    const double soft = soft_reach * max_reach;
    const double start = max_reach - soft;
    if (soft > 0.0 && r > start) r = start + soft * (1.0 - std::exp((start - r) / soft));
  }
  const bool straight = r >= max_reach;
  const bool folded = r <= min_reach;
  r = straight ? max_reach : (folded ? min_reach : r);

  // Law of cosines: the middle joint projects onto the root → target line at
  // x = (l1² - l2² + r²) / 2r and sits h = sqrt(l1² - x²) beside it. h is computed once and
  // shared by both bones, so the two bone vectors sum to r·dir to rounding even near full
  // extension, where the angles themselves are ill-conditioned. Clamped chains get the exact
  // straight or folded x (h = 0) rather than rounding noise of order sqrt(eps).
  double x = ((l1 - l2) * (l1 + l2) + r * r) / (r > 0.0 ? 2.0 * r : 1.0);
  x = x < l1 ? x : l1;
  x = x > -l1 ? x : -l1;
  x = straight ? l1 : (folded ? (l1 >= l2 ? l1 : -l1) : x);
  const double h = std::sqrt(std::fmax(0.0, (l1 - x) * (l1 + x)));

  // Bone directions (cos, sin) in the frame (dir, left normal of dir).
  double ux = 1.0, uy = 0.0;
  if (l1 > 0.0) {
    const double inv = 1.0 / l1;
    ux = x * inv;
    uy = b * h * inv;
  }
  double lx = ux, ly = uy;  // a zero-length lower bone continues the upper one
  if (l2 > 0.0) {
    const double inv = 1.0 / l2;
    lx = (r - x) * inv;
    ly = -b * h * inv;
  }

  TwoBoneIkResult& out = result;
  out.upper_dir = {static_cast<float>(ux * dir_x - uy * dir_y),
                   static_cast<float>(ux * dir_y + uy * dir_x)};
  out.lower_dir = {static_cast<float>(lx * dir_x - ly * dir_y),
                   static_cast<float>(lx * dir_y + ly * dir_x)};
  out.middle = {static_cast<float>(root.x + l1 * (ux * dir_x - uy * dir_y)),
                static_cast<float>(root.y + l1 * (ux * dir_y + uy * dir_x))};
  out.end = {static_cast<float>(root.x + r * dir_x), static_cast<float>(root.y + r * dir_y)};
  out.reached = std::fabs(dist - r) <= 1e-5 * max_reach;
  if (compute_angles) {
    out.upper_angle = fast_atan2(out.upper_dir.y, out.upper_dir.x);
    // Relative angle from the local directions: atan2(cross, dot), independent of dir.
    out.lower_angle = fast_atan2(static_cast<float>(ux * ly - uy * lx),
                                 static_cast<float>(ux * lx + uy * ly));
  }
  return true;
}

TwoBoneIkResult solve_two_bone_ik(glm::vec2 root, float upper_length, float lower_length,
                                  glm::vec2 target, float bend_sign, float soft_reach) {
  TwoBoneIkJob job;
  job.root = root;
  job.upper_length = upper_length;
  job.lower_length = lower_length;
  job.target = target;
  job.bend_sign = bend_sign;
  job.soft_reach = soft_reach;
  const bool ok = job.run();
  OSSA_ASSERT(ok, "solve_two_bone_ik: invalid inputs (see TwoBoneIkJob::validate)");
  return job.result;
}

}  // namespace ossa
