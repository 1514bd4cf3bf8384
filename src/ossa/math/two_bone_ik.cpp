#include "ossa/math/two_bone_ik.h"

#include "ossa/assert.h"
#include "ossa/math/angle.h"

#include <cmath>

namespace ossa {

namespace {

bool finite(glm::vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }

// The inputs' contract (validate()), on plain values.
inline bool valid_inputs(glm::vec2 root, float upper_length, float lower_length, glm::vec2 target,
                         float bend_sign, float soft_reach) {
  return finite(root) && finite(target) && std::isfinite(upper_length) &&
         std::isfinite(lower_length) && upper_length >= 0.0f && lower_length >= 0.0f &&
         (bend_sign == 1.0f || bend_sign == -1.0f) && soft_reach >= 0.0f &&
         soft_reach < 1.0f;
}

// Shared by validate() and run(): a public member function is not inlined into run() in a
// -fPIC build (it could be interposed), and run() is hot.
inline bool valid(const TwoBoneIkJob& j) {
  return valid_inputs(j.root, j.upper_length, j.lower_length, j.target, j.bend_sign, j.soft_reach);
}

// run()'s solve on plain values, written into `out` (the angles only when compute_angles): the
// job and the solve_* shortcuts share it, so that a shortcut neither builds a job nor copies
// its result out.
[[gnu::always_inline]] inline void solve_into(glm::vec2 root, float upper_length, float lower_length, glm::vec2 target,
                                             float bend_sign, float soft_reach, bool compute_angles, TwoBoneIkResult& out) {
  // The triangle is solved in double: the lower bone's direction is (r - l1 c, -l1 s) / l2
  // (below), and with a short lower bone (foot-sized l2 under a long thigh) float rounding of
  // c and s would be amplified by l1 / l2. In double that amplification stays far below float
  // output precision, and every product below stays a normal number for any float input.
  const double l1 = upper_length;
  const double l2 = lower_length;
  const double b = bend_sign;
  const double dx = static_cast<double>(target.x) - root.x;
  const double dy = static_cast<double>(target.y) - root.y;
  const double dist2 = dx * dx + dy * dy;
  const double dist = std::sqrt(dist2);

  // Effective distance r of the end from the root. Soft reach (as in "soft IK"): beyond
  // start = (1 - soft_reach) * reach the end approaches full reach exponentially,
  // r = start + soft (1 - e^(-(dist - start) / soft)): continuous with slope 1 at start, and
  // r <= dist because 1 - e^-y <= y, so the end never passes the target.
  const double max_reach = l1 + l2;
  const double min_reach = std::fabs(l1 - l2);
  double r = dist;
  double r2 = dist2;
  if (soft_reach > 0.0f) {
    const double soft = soft_reach * max_reach;
    const double start = max_reach - soft;
    if (soft > 0.0 && r > start) {
      r = start + soft * (1.0 - std::exp((start - r) / soft));
      r2 = r * r;
    }
  }
  // Clamp r and, independently, r² (minsd / maxsd, no branches): the triangle's height below
  // needs only r², so its square root does not wait for the one of dist.
  r = r < max_reach ? r : max_reach;
  r = r > min_reach ? r : min_reach;
  r2 = r2 < max_reach * max_reach ? r2 : max_reach * max_reach;
  r2 = r2 > min_reach * min_reach ? r2 : min_reach * min_reach;

  // Law of cosines. In the frame (dir, left normal of dir) the upper bone is (c, s) with
  // c = cos(root angle) = w / (2 l1 r), w = l1² - l2² + r², and s = bend · g / (2 l1 r), where
  // g = sqrt(4 l1² r² - w²) is 2 r × the middle joint's height above the line. The lower bone
  // is (r - l1 c, -l1 s) / l2: both bones share s, so they sum to (r, 0) to rounding even near
  // full extension, where the angles themselves are ill-conditioned.
  const double w = (l1 - l2) * (l1 + l2) + r2;
  const double g2 = 4.0 * l1 * l1 * r2 - w * w;  // >= 0 up to rounding at the reach limits
  const double g = std::sqrt(g2 > 0.0 ? g2 : 0.0);

  // The relative lower angle φ straight from the triangle: cos φ = (r² - l1² - l2²) / 2 l1 l2,
  // sin φ = -bend · g / 2 l1 l2, so its atan2 needs neither the bone directions nor the
  // division below and runs in parallel with them. The same expression gives 0 for a straight
  // chain (also with zero-length bones) and ±π for a folded one. Both arguments are scaled by
  // 1 / reach² so that they are normal floats for any chain size.
  float lower_angle = 0.0f;
  if (compute_angles) {
    const double scale = max_reach > 0.0 ? 1.0 / (max_reach * max_reach) : 1.0;
    lower_angle = fast_atan2(static_cast<float>(-b * g * scale),
                             static_cast<float>((r2 - l1 * l1 - l2 * l2) * scale));
  }

  double dir_x = 1.0, dir_y = 0.0;  // a target on the root points the chain along +x
  double ux = 1.0, uy = 0.0;        // upper bone direction, local frame
  double lx = 1.0, ly = 0.0;        // lower bone direction, local frame
  if (l1 > 0.0 && l2 > 0.0 && dist > 1e-30) {
    // Regular chain (r > 0): one division serves 1/dist, 1/(2 l1 r) and 1/l2. With float
    // inputs and dist > 1e-30, k * dist stays within double range (1e-165 .. 1e157).
    const double k = 2.0 * l1 * l2 * r;
    const double q = 1.0 / (k * dist);
    dir_x = dx * (q * k);
    dir_y = dy * (q * k);
    const double inv_2l1r = q * l2 * dist;
    const double c = w * inv_2l1r;
    const double s = b * g * inv_2l1r;
    const double inv_l2 = q * (2.0 * l1 * r * dist);
    ux = c;
    uy = s;
    lx = (r - l1 * c) * inv_l2;
    ly = -l1 * s * inv_l2;
  } else {
    // Degenerate chain: a zero-length bone (the chain stays straight towards the target: a
    // zero upper bone leaves the lower one pointing at it, a zero lower bone continues the
    // upper one) or a target on the root with two real bones: folded flat along +x, the longer
    // bone first, so that the end sits at r = |l1 - l2| on the ray.
    if (dist > 1e-30) {
      dir_x = dx / dist;
      dir_y = dy / dist;
    }
    if (l1 > 0.0 && l2 > 0.0) {
      ux = l1 >= l2 ? 1.0 : -1.0;
      lx = -ux;
    }
  }

  const double upper_x = ux * dir_x - uy * dir_y;
  const double upper_y = ux * dir_y + uy * dir_x;
  out.upper_dir = {static_cast<float>(upper_x), static_cast<float>(upper_y)};
  out.lower_dir = {static_cast<float>(lx * dir_x - ly * dir_y),
                   static_cast<float>(lx * dir_y + ly * dir_x)};
  out.middle = {static_cast<float>(root.x + l1 * upper_x), static_cast<float>(root.y + l1 * upper_y)};
  out.end = {static_cast<float>(root.x + r * dir_x), static_cast<float>(root.y + r * dir_y)};
  out.reached = std::fabs(dist - r) <= 1e-5 * max_reach;
  if (compute_angles) {
    out.upper_angle = fast_atan2(out.upper_dir.y, out.upper_dir.x);
    out.lower_angle = lower_angle;
  }
}

[[gnu::always_inline]] inline TwoBoneIkResult solve(glm::vec2 root, float upper_length, float lower_length, glm::vec2 target,
                                                    float bend_sign, float soft_reach, bool compute_angles) {
  // As a fresh TwoBoneIkJob's run() would.
  const bool ok = valid_inputs(root, upper_length, lower_length, target, bend_sign, soft_reach);
  OSSA_ASSERT(ok, "solve_two_bone_ik: invalid inputs (see TwoBoneIkJob::validate)");
  TwoBoneIkResult out;
  solve_into(root, upper_length, lower_length, target, bend_sign, soft_reach, compute_angles, out);
  return out;
}

}  // namespace

bool TwoBoneIkJob::validate() const { return valid(*this); }

bool TwoBoneIkJob::run() {
  if (!valid(*this)) return false;
  solve_into(root, upper_length, lower_length, target, bend_sign, soft_reach, compute_angles, result);
  return true;
}

TwoBoneIkResult solve_two_bone_ik(glm::vec2 root, float upper_length, float lower_length,
                                  glm::vec2 target, float bend_sign, float soft_reach) {
  return solve(root, upper_length, lower_length, target, bend_sign, soft_reach, true);
}

TwoBoneIkResult solve_two_bone_ik_directions(glm::vec2 root, float upper_length, float lower_length,
                                             glm::vec2 target, float bend_sign) {
  return solve(root, upper_length, lower_length, target, bend_sign, 0.0f, false);
}

}  // namespace ossa
