#pragma once
// Leg geometry: what a leg of the rig reaches, as every stage asks it — the ankle of a foot
// rolled about its contact point, the point the girdle joint must stay within reach of, and
// whether a stance leg standing where it stands would cut the level. Pure functions of the rig,
// the body frame and the level, shared by the step stage, body motion, body placement and the
// leg IK (no stage's own rule lives here). Facing space (_fs, anim_state.h), metres.

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "ossa/anim/anim_state.h"
#include "ossa/math/two_bone_ik.h"
#include "ossa/skeleton/mid_joint.h"

namespace ossa::anim {

namespace detail {
// leg_ankle's rare part (leg_ik.cpp): turns a rolled foot back until it clears the level;
// false if it already did.
bool limit_foot_roll(const AnimContext& ctx, const BodyFrame& body, int leg, glm::vec2 contact_fs, glm::vec2* foot_dir);
}  // namespace detail

// (leg_ankle and leg_anchor are inline: every stage asks them for every leg, some several
// times a tick.)

// The ankle of leg `leg` for a contact point and girdle joint (_fs), and the foot bone's
// direction: the rest angle unless that over-extends the leg, else pivoted about the contact
// (no further than the level allows, when `level_aware`), or that brings the ankle closer to
// the joint than the leg reaches (unless `least` is false: a swinging foot, whose ankle the
// leg IK lifts and tucks anyway). *limited: the level kept the foot from rolling as far as the
// leg's reach needs.
[[gnu::always_inline]] inline glm::vec2 leg_ankle(const AnimContext& ctx, const BodyFrame& body, int leg, glm::vec2 contact_fs,
                                                  glm::vec2 joint_fs, bool level_aware, const Clearance& near,
                                                  glm::vec2* foot_dir, bool* limited, bool least = true) {
  // Hooves and toes roll: with the contact point c fixed, the ankle a(θ) = c - F·u(θ) lies on
  // a circle of the foot's length F around it. The leg (joint j → ankle) reaches from m to r
  // (least_reach, leg_reach), so m <= |a - j| <= r, i.e. q_r <= u(θ)·d <= q_m with d = c - j
  // and q_x = (|d|² + F² - x²) / 2F: a band of directions between β_r = acos(q_r / |d|) and
  // β_m of d. The foot keeps its rest direction inside the band and turns to its nearer edge
  // outside it (into line with d when the band is empty; m = r for a leg with a vanishing bone,
  // whose ankle can only lie at r).
  const RigLeg& info = ctx.rig.legs[leg];
  *foot_dir = info.foot_dir_ms;
  if (limited) *limited = false;
  const float F = info.foot_span;
  if (F <= 0.0f) return contact_fs;  // flat contact: the contact point is the ankle
  const glm::vec2 d = contact_fs - joint_fs;
  const float dd = glm::dot(d, d);
  const float along = glm::dot(d, info.foot_dir_ms);
  const float q_r = (dd + F * F - info.leg_reach * info.leg_reach) / (2.0f * F);
  const float m = least ? info.least_reach : 0.0f;
  const float q_m = (dd + F * F - m * m) / (2.0f * F);
  if ((along < q_r || along > q_m) && dd > 1e-12f) {
    const float len = std::sqrt(dd);
    const glm::vec2 n = d / len;
    const float cos_b = std::clamp((along < q_r ? q_r : q_m) / len, -1.0f, 1.0f);
    const float sin_b = std::sqrt(std::max(1.0f - cos_b * cos_b, 0.0f));
    // The side of d the rest direction lies on.
    const float side = n.x * info.foot_dir_ms.y - n.y * info.foot_dir_ms.x >= 0.0f ? 1.0f : -1.0f;
    *foot_dir = {cos_b * n.x - side * sin_b * n.y, side * sin_b * n.x + cos_b * n.y};
    if (level_aware && *foot_dir != info.foot_dir_ms && !near.clear_above(std::min(contact_fs.y, contact_fs.y - F * foot_dir->y)) &&
        detail::limit_foot_roll(ctx, body, leg, contact_fs, foot_dir) && limited) {
      *limited = true;
    }
  }
  return contact_fs - F * *foot_dir;
}

// The point the girdle joint of leg `leg` must stay within *radius of: the contact point
// (foot free to roll) or the ankle (foot held by the level).
[[gnu::always_inline]] inline glm::vec2 leg_anchor(const AnimContext& ctx, const BodyFrame& body, int leg, glm::vec2 contact_fs,
                                                   glm::vec2 joint_fs, const Clearance& near, float* radius) {
  glm::vec2 dir;
  bool limited = false;
  const glm::vec2 ankle = leg_ankle(ctx, body, leg, contact_fs, joint_fs, true, near, &dir, &limited);
  if (!limited) {
    *radius = ctx.rig.legs[leg].contact_reach;
    return contact_fs;
  }
  *radius = ctx.rig.legs[leg].leg_reach;
  return ankle;
}

// How far stance foot `foot` of leg `leg` lies beyond what its leg reaches with the girdle
// joint at joint_fs (metres; ≤ 0: in reach) — body placement's clamp 1 measure.
inline float leg_overreach(const AnimContext& ctx, const BodyFrame& body, int leg, const FootState& foot, glm::vec2 joint_fs) {
  float r;
  const glm::vec2 anchor = leg_anchor(ctx, body, leg, body.to_fs(foot.pos_ws), joint_fs, foot.stance_clear, &r);
  return glm::length(anchor - joint_fs) - r;
}
// Would leg `leg`'s chain (joint, knee, ankle, toe), its foot standing where it stands, cut
// into a box with its girdle joint at joint_fs? with_flesh: or its drawn outline
// (leg_flesh_hits) a box whose top rises above the foot's contact.
bool stance_leg_hits(const AnimContext& ctx, const BodyFrame& body, int leg, const FootState& foot, glm::vec2 joint_fs,
                     bool with_flesh = false);

// How far the body must go back (world metres, >= 0) for its stance legs' drawn outline
// (RigLeg::flesh_outline, as the leg IK draws each leg, its foot where it stands) to leave the
// faces of the boxes ahead of their feet that rise above them (a triceratops blocked at a post,
// its shoulder's flesh in the post's corner; a pigeon blocked at a riser, its knee in it): 0
// when clear, or when no shift up to `most` clears them, or where it would lay a leg's outline
// deeper into a box behind its foot. Standing still: its feet stay, its legs follow the body.
float stance_flesh_push(const AnimContext& ctx, const BodyFrame& body, const FootSet& feet, float most);
// How far of `dx` (world metres along x) the body may move with its stance legs' drawn outline,
// the legs following it, going no deeper into the face of a box ahead of a foot that rises
// above the leg's joint (a wall; a riser the legs climb is none: the triceratops's shoulder met
// default.json's post before its trunk did, the pigeon's knee a riser as it tried the way
// ahead again).
float stance_flesh_advance(const AnimContext& ctx, const BodyFrame& body, const FootSet& feet, float dx);

// A limb's skin frames (anim_rig.h kLimbSkinFrames) from its three bone frames frames[0..2]:
// frames[3 + i] the frame of mid joint mids[i] (skeleton/mid_joint.h), as the body's palette
// has it.
inline void limb_skin_frames(const std::vector<MidJoint>& mids, Mat2x3* frames) {
  for (size_t i = 0; i < mids.size(); ++i) {
    const MidJoint& j = mids[i];
    frames[3 + i] = j.level ? level_frame(j, frames[j.child]) : mid_joint_frame(frames[j.parent], frames[j.child], j.turn, j.rest_half);
  }
}
// A point of a limb's drawn outline (anim_rig.h LimbFleshPoint) posed with the limb's skin
// frames (limb_skin_frames), in their space.
inline glm::vec2 posed_flesh(const LimbFleshPoint& q, const Mat2x3* frames) {
  glm::vec2 p = q.weight[0] * frames[q.frame[0]].apply(q.local[0]);
  for (int i = 1; i < q.count; ++i) p += q.weight[static_cast<size_t>(i)] * frames[q.frame[static_cast<size_t>(i)]].apply(q.local[static_cast<size_t>(i)]);
  return p;
}

// Does the leg's drawn outline (RigLeg::flesh_outline), posed with its bones (the upper from
// joint_fs along ik.upper_dir, the lower from ik.middle along ik.lower_dir, the foot from
// ik.end along foot_dir; frame space), pass through a collider whose top lies above top_over?
// false for a leg without one.
bool leg_flesh_hits(const AnimContext& ctx, const BodyFrame& body, const RigLeg& info, glm::vec2 joint_fs, const TwoBoneIkResult& ik,
                    glm::vec2 foot_dir, float top_over = -INFINITY);
// How deep that outline lies in those colliders, metres (level.h segment_penetration; 0: clear).
float leg_flesh_depth(const AnimContext& ctx, const BodyFrame& body, const RigLeg& info, glm::vec2 joint_fs, const TwoBoneIkResult& ik,
                      glm::vec2 foot_dir, float top_over = -INFINITY);

}  // namespace ossa::anim
