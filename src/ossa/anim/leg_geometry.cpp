#include "ossa/anim/leg_geometry.h"

#include <array>

#include "ossa/anim/anim_math.h"
#include "ossa/anim/leg_ik.h"
#include "ossa/math/two_bone_ik.h"

namespace ossa::anim {

namespace {

// A rolled foot that would sweep into a step turns back by bisection in this many halvings.
constexpr int kRollBisections = 6;
// A standing leg's flesh meets only boxes whose top rises this far above its foot's contact
// (not the ground it stands on).
constexpr float kContactSlack = 1e-3f;

}  // namespace

// leg_ankle's rare part (leg_geometry.h), out of line so that the common one stays small.
[[gnu::noinline]] bool detail::limit_foot_roll(const AnimContext& ctx, const BodyFrame& body, int leg, glm::vec2 contact_fs,
                                               glm::vec2* foot_dir) {
  const RigLeg& info = ctx.rig.legs[leg];
  const float F = info.foot_span;
  auto clear = [&](glm::vec2 u) {
    const glm::vec2 seg[2] = {body.to_ws(contact_fs - F * u), body.to_ws(contact_fs)};
    return !polyline_hits_level(ctx.level, seg, 2, ctx.hits);
  };
  if (clear(*foot_dir)) return false;
  const glm::vec2 rest = info.foot_dir_ms;
  const float full = std::atan2(rest.x * foot_dir->y - rest.y * foot_dir->x, glm::dot(rest, *foot_dir));
  float lo = 0.0f, hi = 1.0f;  // fractions of the roll: lo clears, hi does not
  bisect(lo, hi, kRollBisections, [&](float mid) { return clear(rotate(rest, mid * full)); });
  *foot_dir = lo > 0.0f ? rotate(rest, lo * full) : rest;
  return true;
}

bool stance_leg_hits(const AnimContext& ctx, const BodyFrame& body, int leg, const FootState& f, glm::vec2 joint_fs, bool with_flesh) {
  const RigLeg& info = ctx.rig.legs[leg];
  const glm::vec2 contact = body.to_fs(f.pos_ws);
  glm::vec2 dir;
  const glm::vec2 ankle = leg_ankle(ctx, body, leg, contact, joint_fs, true, f.stance_clear, &dir, nullptr);
  const TwoBoneIkResult ik = solve_two_bone_ik_directions(joint_fs, info.upper, info.lower, ankle, info.bend);
  const glm::vec2 tip = ik.end + info.foot_length * dir;
  const glm::vec2 p[4] = {body.to_ws(joint_fs), body.to_ws(ik.middle), body.to_ws(ik.end), body.to_ws(tip)};
  if (polyline_hits_level(ctx.level, p, info.foot_length > 0.0f ? 4 : 3, ctx.hits)) return true;
  if (!with_flesh || info.flesh_outline.empty()) return false;
  // The flesh as the leg IK draws the leg (leg_ik.h).
  const StanceLegPose drawn = stance_leg_pose(ctx, body, leg, contact, joint_fs, f.stance_clear);
  return leg_flesh_hits(ctx, body, info, joint_fs, drawn.ik, drawn.foot_dir, f.pos_ws.y + kContactSlack);
}

bool leg_flesh_hits(const AnimContext& ctx, const BodyFrame& body, const RigLeg& info, glm::vec2 joint_fs, const TwoBoneIkResult& ik,
                    glm::vec2 foot_dir, float top_over) {
  const size_t n = info.flesh_outline.size();
  if (n < 2) return false;
  const Mat2x3 frames[3] = {frame_matrix(ik.upper_dir, joint_fs), frame_matrix(ik.lower_dir, ik.middle), frame_matrix(foot_dir, ik.end)};
  std::array<glm::vec2, kLimbFleshPoints + 1> p;
  for (size_t i = 0; i < n; ++i) p[i] = body.to_ws(posed_flesh(info.flesh_outline[i], frames));
  p[n] = p[0];
  return polyline_hits_level(ctx.level, p.data(), static_cast<int>(n + 1), ctx.hits, -INFINITY, top_over);
}

}  // namespace ossa::anim
