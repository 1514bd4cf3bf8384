#include "ossa/anim/leg_geometry.h"

#include <array>

#include "ossa/anim/anim_math.h"
#include "ossa/anim/animator_params.h"
#include "ossa/anim/leg_ik.h"
#include "ossa/anim/level_probe.h"
#include "ossa/math/two_bone_ik.h"

namespace ossa::anim {

namespace {

// A rolled foot that would sweep into a step turns back by bisection in this many halvings.
constexpr int kRollBisections = 6;
// A standing leg's flesh meets only boxes whose top rises this far above its foot's contact
// (not the ground it stands on).
constexpr float kContactSlack = 1e-3f;
// stance_flesh_push: the body goes this much further back than the outline lies in a face, and
// moves at most this many times (each a step by the depth still left: the legs lean as it goes).
constexpr float kFleshPushMargin = 1e-3f;
constexpr int kFleshPushTries = 4;
// stance_flesh_advance: halvings of the move that would take the outline deeper.
constexpr int kFleshAdvanceBisections = 6;

// A leg's drawn outline (RigLeg::flesh_outline) posed with its bones (the upper from joint_fs
// along ik.upper_dir, the lower from ik.middle, the foot from ik.end along foot_dir; frame
// space) into p[0..n] in world space, closed (p[n] = p[0]); its bounds. n: the outline's size.
using LegOutline = std::array<glm::vec2, kLimbFleshPoints + 1>;
Box pose_leg_outline(const BodyFrame& body, const RigLeg& info, glm::vec2 joint_fs, const TwoBoneIkResult& ik, glm::vec2 foot_dir,
                     LegOutline& p) {
  const size_t n = info.flesh_outline.size();
  Mat2x3 frames[kLimbSkinFrames] = {frame_matrix(ik.upper_dir, joint_fs), frame_matrix(ik.lower_dir, ik.middle), frame_matrix(foot_dir, ik.end)};
  limb_skin_frames(info.flesh_mids, frames);
  Box bound{glm::vec2(1e30f), glm::vec2(-1e30f)};
  for (size_t k = 0; k < n; ++k) {
    p[k] = body.to_ws(posed_flesh(info.flesh_outline[k], frames));
    bound = bound.united(Box{p[k], p[k]});
  }
  p[n] = p[0];
  return bound;
}

// How deep the stance legs' drawn outline (as the leg IK draws each leg, its foot where it
// stands) lies in the boxes that rise above its foot (walls_only: above the leg's joint), world
// metres along x: *ahead into the face of a box ahead of the foot (facing), *behind into that
// of one behind it.
void stance_flesh_depth(const AnimContext& ctx, const BodyFrame& body, const FootSet& feet, bool walls_only, float* ahead,
                        float* behind) {
  const AnimRig& rig = ctx.rig;
  *ahead = *behind = 0.0f;
  GirdleJointFs joints;
  LegOutline p;
  for (size_t i = 0; i < rig.legs.size(); ++i) {
    const RigLeg& info = rig.legs[i];
    const FootState& f = feet.of_leg(static_cast<int>(i));
    const size_t n = info.flesh_outline.size();
    if (f.state != LegState::kStance || n < 2) continue;
    const glm::vec2 joint_fs = joints.of(rig, body, info.girdle);
    const StanceLegPose drawn = stance_leg_pose(ctx, body, static_cast<int>(i), body.to_fs(f.pos_ws), joint_fs, f.stance_clear);
    const Box bound = pose_leg_outline(body, info, joint_fs, drawn.ik, drawn.foot_dir, p);
    ctx.hits.clear();
    ctx.level.overlapping(bound, ctx.hits);
    for (int h : ctx.hits) {
      const Box& c = ctx.level.box(h);
      // (Not the ground it stands on.)
      if (!(c.max_ws.y > (walls_only ? body.to_ws(joint_fs).y : f.pos_ws.y + kContactSlack))) continue;
      const bool front = body.facing > 0 ? c.min_ws.x > f.pos_ws.x : c.max_ws.x < f.pos_ws.x;
      for (size_t k = 0; k < n; ++k) {
        float x0, x1;
        if (!segment_x_within(p[k], p[k + 1], c.min_ws.y, c.max_ws.y, &x0, &x1)) continue;
        x0 = std::max(x0, c.min_ws.x);
        x1 = std::min(x1, c.max_ws.x);
        if (!(x0 < x1)) continue;
        // Into the face toward the foot: the near one of a box ahead, the far one behind.
        const float into = (body.facing > 0) == front ? x1 - c.min_ws.x : c.max_ws.x - x0;
        float& depth = front ? *ahead : *behind;
        depth = std::max(depth, into);
      }
    }
  }
}

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
  LegOutline p;
  pose_leg_outline(body, info, joint_fs, ik, foot_dir, p);
  return polyline_hits_level(ctx.level, p.data(), static_cast<int>(n + 1), ctx.hits, -INFINITY, top_over);
}

float leg_flesh_depth(const AnimContext& ctx, const BodyFrame& body, const RigLeg& info, glm::vec2 joint_fs, const TwoBoneIkResult& ik,
                      glm::vec2 foot_dir, float top_over) {
  const size_t n = info.flesh_outline.size();
  if (n < 2) return 0.0f;
  LegOutline p;
  const Box bound = pose_leg_outline(body, info, joint_fs, ik, foot_dir, p);
  ctx.hits.clear();
  ctx.level.overlapping(bound, ctx.hits);
  float depth = 0.0f;
  if (ctx.hits.empty()) return depth;
  std::erase_if(ctx.hits, [&](int h) { return !(ctx.level.box(h).top() > top_over); });
  for (size_t i = 0; i < n; ++i) depth = std::max(depth, segment_penetration(ctx.level, p[i], p[i + 1], ctx.hits));
  return depth;
}

float stance_flesh_push(const AnimContext& ctx, const BodyFrame& body, const FootSet& feet, float most) {
  if (ctx.rig.legs.empty() || !(most > 0.0f)) return 0.0f;
  float ahead, behind0;
  stance_flesh_depth(ctx, body, feet, false, &ahead, &behind0);
  BodyFrame moved = body;
  float push = 0.0f;
  for (int i = 0; i < kFleshPushTries && ahead > 0.0f; ++i) {
    push += ahead + kFleshPushMargin;
    if (push > most) return 0.0f;
    moved.x_ws = body.x_ws - static_cast<float>(body.facing) * push;
    float behind;
    stance_flesh_depth(ctx, moved, feet, false, &ahead, &behind);
    if (behind > behind0 + kFleshPushMargin) return 0.0f;
  }
  return ahead > 0.0f ? 0.0f : push;
}

float stance_flesh_advance(const AnimContext& ctx, const BodyFrame& body, const FootSet& feet, float dx) {
  const AnimRig& rig = ctx.rig;
  if (dx == 0.0f || rig.legs.empty()) return dx;
  // Only a box rising above the leg's joint is a wall (a riser it steps up, its flesh at the
  // riser's corner as it goes, is not: the swing and the foothold see to that).
  // First, cheaply: any box about the stance legs that rises so high?
  Box around{glm::vec2(1e30f), glm::vec2(-1e30f)};
  float lowest_joint = 1e30f;
  GirdleJointFs joints;
  for (size_t i = 0; i < rig.legs.size(); ++i) {
    const FootState& f = feet.of_leg(static_cast<int>(i));
    if (f.state != LegState::kStance || rig.legs[i].flesh_outline.empty()) continue;
    const glm::vec2 joint = body.to_ws(joints.of(rig, body, rig.legs[i].girdle));
    const float r = rig.legs[i].reach + std::max({rig.legs[i].flesh_margin[0], rig.legs[i].flesh_margin[1], rig.legs[i].flesh_margin[2]});
    around = around.united(Box{joint - glm::vec2(r), joint + glm::vec2(r)});
    lowest_joint = std::min(lowest_joint, joint.y);
  }
  if (lowest_joint > 1e29f) return dx;
  around.min_ws.x = std::min(around.min_ws.x, around.min_ws.x + dx);
  around.max_ws.x = std::max(around.max_ws.x, around.max_ws.x + dx);
  ctx.hits.clear();
  ctx.level.overlapping(around, ctx.hits);
  if (std::none_of(ctx.hits.begin(), ctx.hits.end(), [&](int h) { return ctx.level.box(h).top() > lowest_joint; })) return dx;
  float now, behind;
  stance_flesh_depth(ctx, body, feet, true, &now, &behind);
  BodyFrame moved = body;
  auto deeper = [&](float t) {
    moved.x_ws = body.x_ws + t * dx;
    float ahead;
    stance_flesh_depth(ctx, moved, feet, true, &ahead, &behind);
    return ahead > now + kFleshPushMargin;
  };
  if (!deeper(1.0f)) return dx;
  float lo = 0.0f, hi = 1.0f;  // lo: no deeper; hi: deeper
  bisect(lo, hi, kFleshAdvanceBisections, [&](float t) { return !deeper(t); });
  return lo * dx;
}

}  // namespace ossa::anim
