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

#include <glm/vec2.hpp>

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
/// for callers that build matrices straight from the directions.
TwoBoneIkResult solve_two_bone_ik_directions(glm::vec2 root, float upper_length, float lower_length,
                                             glm::vec2 target, float bend_sign);

}  // namespace ossa
