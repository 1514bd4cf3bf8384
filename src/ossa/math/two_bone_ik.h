#pragma once
// Analytic two-bone inverse kinematics in 2D (thigh + shank, upper arm + forearm): the solver
// that puts every foot on the ground (DESIGN.md §4, §7). Written as a small job in the style of
// ozz-animation's IKTwoBoneJob: fill the inputs, call run(), read `result`.
//
//        middle
//         /\            upper bone: root → middle, length upper_length
//  upper /  \ lower     lower bone: middle → end,  length lower_length
//       /    \          bend_sign = +1: middle on the LEFT of root → target (counter-clockwise
//   root ---- end ~ target            side), -1: on the right.
//
// Guarantees (all covered by property tests over random chains):
//  - reachable target (|upper - lower| <= distance <= upper + lower): `end` is the target within
//    1e-5 × (upper + lower), and FK from the output angles lands there too;
//  - beyond reach: the chain is fully extended along root → target; closer than
//    |upper - lower|: fully folded with its end on the root → target ray;
//  - degenerate input (target on the root, zero lengths, coincident points): a defined finite
//    pose — the root → target direction is taken as +x — never NaN;
//  - mirroring root and target (x → -x) and flipping bend_sign mirrors the pose exactly:
//    upper_angle → π - upper_angle (mod 2π), lower_angle → -lower_angle, so a creature that turns
//    around keeps its knees bending the right way;
//  - soft_reach > 0 eases the chain into full extension instead of snapping straight, is
//    continuous in the target, and never places the end beyond the target.
//
// Cost: no allocation, no libm trigonometry, no data-dependent branches on the regular path.
// The triangle is solved in double with the law of cosines — the root angle's cosine and the
// middle joint's height (one sqrt each) — and one division serves 1/distance, 1/(2 l1 r) and
// 1/l2; positions and the bone directions (cos/sin of the bone angles) follow from those by
// multiplication. The angles, needed by forward kinematics, cost two branch-free fast_atan2
// (math/angle.h); compute_angles = false skips them. tests/bench/math_bench.cpp measures both
// forms per solve against a naive solver (atan2 + two acos, then cos/sin of both bones) with
// the same outputs: "ik" (positions + directions, compute_angles = false) and
// "ik_with_angles" (angles too, the form FK uses).
//
// Range: any finite float input gives a finite result; the triangle is solved in double, so
// millimetre and kilometre chains are equally accurate. The 1e-5 tolerance is relative to the
// chain; the rounding of the float coordinates themselves comes on top (it matters only when
// |root| is many thousand chain lengths from the origin).

#include <cmath>

#include <glm/vec2.hpp>

#include "ossa/assert.h"
#include "ossa/math/angle.h"

namespace ossa {

/// Output pose. All positions and directions are in the frame of the inputs.
struct TwoBoneIkResult {
  float upper_angle = 0.0f;         // radians in [-π, π], absolute, counter-clockwise from +x
  float lower_angle = 0.0f;         // radians in [-π, π], relative to the upper bone
                                    // (0 = straight; its sign is -bend_sign when bent)
  glm::vec2 upper_dir{1.0f, 0.0f};  // unit direction of the upper bone = (cos, sin)(upper_angle)
  glm::vec2 lower_dir{1.0f, 0.0f};  // unit direction of the lower bone, ABSOLUTE:
                                    // (cos, sin)(upper_angle + lower_angle)
  glm::vec2 middle{0.0f, 0.0f};     // middle joint (knee, elbow) = root + upper_length * upper_dir
  glm::vec2 end{0.0f, 0.0f};        // end effector, on the root → target ray; equals
                                    // middle + lower_length * lower_dir to float precision
  bool reached = false;             // |end - target| <= 1e-5 * (upper_length + lower_length)
};

struct TwoBoneIkJob {
  // --- Inputs -------------------------------------------------------------------------------
  glm::vec2 root{0.0f, 0.0f};    // position of the root joint (start of the upper bone), any
                                 // frame (e.g. _ms creature space), metres
  float upper_length = 0.0f;     // metres, >= 0
  float lower_length = 0.0f;     // metres, >= 0
  glm::vec2 target{0.0f, 0.0f};  // desired end position, same frame as root, metres
  float bend_sign = 1.0f;        // +1: middle joint left of root → target (CCW side), -1: right
  float soft_reach = 0.0f;       // 0 = off; else in (0, 1): the fraction of full reach over which
                                 // the chain eases into full extension (e.g. 0.02); the target is
                                 // then not reached in that band (`reached` is false there)
  bool compute_angles = true;    // false: skip the two atan2; result.upper_angle/lower_angle are
                                 // left unchanged (directions and positions are still written)

  // --- Output -------------------------------------------------------------------------------
  TwoBoneIkResult result;

  /// Finite inputs, lengths >= 0, bend_sign exactly +1 or -1, soft_reach in [0, 1).
  bool validate() const;

  /// Solves the chain into `result`. No allocation. Returns validate(); on false `result` is
  /// left unchanged.
  bool run();
};

/// Convenience wrapper: runs a TwoBoneIkJob (angles included) and returns its result. Asserts
/// that the inputs validate.
TwoBoneIkResult solve_two_bone_ik(glm::vec2 root, float upper_length, float lower_length,
                                  glm::vec2 target, float bend_sign, float soft_reach = 0.0f);

/// The same without the two angles (compute_angles = false): directions, joints and end only,
/// for callers that build matrices straight from the directions. (Inline, below: the animator
/// solves every leg every tick.)
inline TwoBoneIkResult solve_two_bone_ik_directions(glm::vec2 root, float upper_length, float lower_length,
                                                    glm::vec2 target, float bend_sign);

// ---- Inline solve ---------------------------------------------------------------------------
// TwoBoneIkJob::run(), solve_two_bone_ik and solve_two_bone_ik_directions share this code;
// it is here so that the directions-only solve inlines into the animator's leg IK.

namespace detail {

inline bool two_bone_finite(glm::vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }

// The inputs' contract (validate()), on plain values.
inline bool two_bone_valid(glm::vec2 root, float upper_length, float lower_length, glm::vec2 target,
                         float bend_sign, float soft_reach) {
  return two_bone_finite(root) && two_bone_finite(target) && std::isfinite(upper_length) &&
         std::isfinite(lower_length) && upper_length >= 0.0f && lower_length >= 0.0f &&
         (bend_sign == 1.0f || bend_sign == -1.0f) && soft_reach >= 0.0f &&
         soft_reach < 1.0f;
}

// Shared by validate() and run(): a public member function is not inlined into run() in a
// -fPIC build (it could be interposed), and run() is hot.
inline bool two_bone_valid(const TwoBoneIkJob& j) {
  return two_bone_valid(j.root, j.upper_length, j.lower_length, j.target, j.bend_sign, j.soft_reach);
}

// run()'s solve on plain values, written into `out` (the angles only when compute_angles): the
// job and the solve_* shortcuts share it, so that a shortcut neither builds a job nor copies
// its result out.
[[gnu::always_inline]] inline void two_bone_solve_into(glm::vec2 root, float upper_length, float lower_length, glm::vec2 target,
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

[[gnu::always_inline]] inline TwoBoneIkResult two_bone_solve(glm::vec2 root, float upper_length, float lower_length, glm::vec2 target,
                                                    float bend_sign, float soft_reach, bool compute_angles) {
  // As a fresh TwoBoneIkJob's run() would.
  const bool ok = two_bone_valid(root, upper_length, lower_length, target, bend_sign, soft_reach);
  OSSA_ASSERT(ok, "solve_two_bone_ik: invalid inputs (see TwoBoneIkJob::validate)");
  TwoBoneIkResult out;
  two_bone_solve_into(root, upper_length, lower_length, target, bend_sign, soft_reach, compute_angles, out);
  return out;
}

}  // namespace detail

inline TwoBoneIkResult solve_two_bone_ik_directions(glm::vec2 root, float upper_length, float lower_length,
                                                    glm::vec2 target, float bend_sign) {
  return detail::two_bone_solve(root, upper_length, lower_length, target, bend_sign, 0.0f, false);
}

}  // namespace ossa
