// Limbs of the body: legs and arms as tubes along their three bones with muscle near the
// girdle tapering to thin lower segments and the foot; wings as feathered (or membrane)
// outlines around the folded wing bones; fins as fans (body_parts.h).
//
// A limb's knee and ankle blend through three mid-joint frames each (skeleton/mid_joint.h),
// as the bone sprites do, so a bent knee keeps its thickness. Feet end where the bone ends —
// the contact point the animator plants — and every outline point of a limb in the rest
// pose lies on or above the ground; hooves, paws and toes narrow to their contact at 30° or
// more either side, so a foot that tilts by less does not dip below it.

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "ossa/body/body_parts.h"

namespace ossa::body {

namespace {

enum class Foot { kHoof, kPaw, kFlat, kBird, kHand };

// As the bone sprites choose theirs (draw/sprite_choice.cpp).
Foot foot_of(const BodyRig& rig, const Limb& limb) {
  const Creature& c = *rig.creature;
  if (limb.kind == LimbKind::kArm) return Foot::kHand;
  if (c.count(LimbKind::kWing) > 0) return Foot::kBird;
  if (c.contact == ContactMode::kFlat) return Foot::kFlat;
  const glm::vec2 d = rig.bone_dir(limb.bones[2]);
  const float steep = std::fabs(d.y);
  if (steep < 0.5f) return Foot::kFlat;
  const Skeleton& s = c.skeleton;
  return steep > 0.7f && s.length(limb.bones[2]) >= 0.45f * s.length(limb.bones[1]) ? Foot::kHoof : Foot::kPaw;
}

// The limb's chain: girdle joint → knee → ankle → tip, with its mid-joint frames.
struct LimbChain {
  Chain chain;
  std::vector<JointBlend> joints;
  float lengths[3] = {0, 0, 0};
};

LimbChain limb_chain(BodyRig& rig, const Limb& limb, int frames_per_joint, const float radius_at_joint[2]) {
  LimbChain lc;
  const Skeleton& s = rig.creature->skeleton;
  lc.chain.points.push_back(rig.bone_start(limb.bones[0]));
  for (int k = 0; k < 3; ++k) {
    lc.chain.points.push_back(rig.bone_end(limb.bones[k]));
    lc.chain.bones.push_back(limb.bones[k]);
    lc.lengths[k] = s.length(limb.bones[k]);
  }
  lc.chain.start_s = {0.0f, lc.lengths[0], lc.lengths[0] + lc.lengths[1], lc.lengths[0] + lc.lengths[1] + lc.lengths[2]};
  for (int j = 0; j < 2; ++j) {
    const int parent = limb.bones[j], child = limb.bones[j + 1];
    JointBlend blend;
    blend.s = lc.chain.start_s[j + 1];
    // Over about the joint's radius either side, less than half of either bone.
    blend.half_width = std::min({1.2f * radius_at_joint[j], 0.45f * lc.lengths[j], 0.45f * lc.lengths[j + 1]});
    blend.frames.push_back(parent);
    for (int f = 0; f < frames_per_joint; ++f) {
      MidJoint mid;
      mid.parent = parent;
      mid.child = child;
      mid.turn = static_cast<float>(f + 1) / static_cast<float>(frames_per_joint + 1);
      mid.rest_half = mid_joint_half_turn(rig.rest[static_cast<size_t>(parent)], rig.rest[static_cast<size_t>(child)]);
      mid.inverse_bind = inverse(mid_joint_frame(rig.rest[static_cast<size_t>(parent)], rig.rest[static_cast<size_t>(child)], mid.turn));
      blend.frames.push_back(rig.bone_count + static_cast<int>(rig.mid_joints.size()));
      rig.mid_joints.push_back(mid);
    }
    blend.frames.push_back(child);
    if (blend.half_width > 0.0f) lc.joints.push_back(blend);
  }
  return lc;
}

// Sections along the chain with radius r(s) (fixed, soft), the knee and ankle rounded: the
// centre line follows an arc through each bent joint over its blend (so the inside of the bend
// keeps room for the flesh), the dorsal normal follows the arc.
std::vector<Section> sweep(const LimbChain& lc, const std::function<std::array<float, 4>(float s)>& radius, int per_bone) {
  std::vector<float> at;
  for (int k = 0; k < 3; ++k) {
    const float a = lc.chain.start_s[static_cast<size_t>(k)], b = lc.chain.start_s[static_cast<size_t>(k + 1)];
    const int n = k == 2 ? per_bone : per_bone;
    for (int i = 0; i < n; ++i) at.push_back(a + (b - a) * static_cast<float>(i) / n);
  }
  // Extra sections across each joint's blend.
  for (const JointBlend& j : lc.joints) {
    for (int i = -3; i <= 3; ++i) at.push_back(j.s + j.half_width * static_cast<float>(i) / 3.0f);
  }
  at.push_back(lc.chain.length());
  std::sort(at.begin(), at.end());
  at.erase(std::unique(at.begin(), at.end(), [](float a, float b) { return std::fabs(a - b) < 1e-6f; }), at.end());
  at.erase(std::remove_if(at.begin(), at.end(), [&](float s) { return s < 0.0f || s > lc.chain.length(); }), at.end());

  std::vector<Section> out;
  for (const float s : at) {
    Section sec;
    glm::vec2 p = lc.chain.point_at(s), t = lc.chain.tangent_at(s);
    for (const JointBlend& j : lc.joints) {
      const float d = s - j.s;
      if (std::fabs(d) >= j.half_width) continue;
      // A quadratic Bézier from half_width before the joint to half_width after it, with the
      // joint as its control point: tangent to both bones, turning evenly.
      const glm::vec2 a = lc.chain.point_at(j.s - j.half_width), c = lc.chain.point_at(j.s + j.half_width);
      const glm::vec2 m = lc.chain.point_at(j.s);
      const float u = (d + j.half_width) / (2.0f * j.half_width);
      p = (1.0f - u) * (1.0f - u) * a + 2.0f * u * (1.0f - u) * m + u * u * c;
      const glm::vec2 dp = 2.0f * (1.0f - u) * (m - a) + 2.0f * u * (c - m);
      if (glm::length(dp) > 1e-9f) t = glm::normalize(dp);
    }
    sec.centre = p;
    sec.dorsal = dorsal_of(t);
    const std::array<float, 4> r = radius(s);
    sec.top_fixed = r[0];
    sec.top_soft = r[1];
    sec.bottom_fixed = r[2];
    sec.bottom_soft = r[3];
    sec.skin = chain_skin(lc.chain, lc.joints, s);
    sec.s = s;
    out.push_back(sec);
  }
  return out;
}

// The inside of a bent knee or ankle: where the flesh of the two bones would overlap, each
// section's inner side stops at the joint's bisector — a crease — so the outline folds there
// cleanly instead of crossing itself (which untangle_tube could only cut away, heel and all).
void crease(const LimbChain& lc, std::vector<Section>& sections) {
  const std::vector<glm::vec2>& pts = lc.chain.points;
  for (size_t j = 1; j + 1 < pts.size(); ++j) {
    const glm::vec2 m = pts[j];
    const glm::vec2 a = m - pts[j - 1], c = pts[j + 1] - m;
    if (!(glm::length(a) > 1e-9f) || !(glm::length(c) > 1e-9f)) continue;
    const glm::vec2 dp = glm::normalize(a), dc = glm::normalize(c);
    if (glm::dot(dp, dc) > 0.5f) continue;  // bent by less than 60°
    const float turn = dp.x * dc.y - dp.y * dc.x;
    glm::vec2 b = dc - dp;  // into the joint's inside
    b = glm::length(b) > 1e-6f ? glm::normalize(b) : glm::vec2(-dp.y, dp.x) * (turn >= 0.0f ? 1.0f : -1.0f);
    const glm::vec2 nb(-b.y, b.x);
    for (Section& sec : sections) {
      // A chain turning left has its inside on the left: the bottom (dorsal is the right).
      const bool bottom = turn >= 0.0f;
      const glm::vec2 n = bottom ? -sec.dorsal : sec.dorsal;
      const float denom = glm::dot(n, nb);
      if (std::fabs(denom) < 1e-6f) continue;
      const float t = glm::dot(m - sec.centre, nb) / denom;
      if (t < 0.0f) continue;
      float& cap = bottom ? sec.bottom_cap : sec.top_cap;
      cap = std::min(cap, 0.96f * t);  // a hair short: the two sides never touch
    }
  }
}

glm::vec4 hoof_colour() { return {0.16f, 0.13f, 0.11f, 1.0f}; }
glm::vec4 claw_colour() { return {0.25f, 0.21f, 0.17f, 1.0f}; }
glm::vec4 scale_colour() { return {0.72f, 0.6f, 0.36f, 1.0f}; }

// A leg's contact frame (TubePlan::contact_entry): a level frame at the point the animator
// plants — the foot's tip, or its heel (the ankle) for flat contact — turned as the foot is at
// rest. A hoof follows it whole; a paw's or bird's toes and a heel over about three radii.
void plant_contact(BodyRig& rig, const Limb& limb, Foot foot, float r_ankle, float r_toe, TubePlan& tube) {
  const Creature& c = *rig.creature;
  if (rig.bone_count + static_cast<int>(rig.mid_joints.size()) >= 256) return;  // uint8 indices
  const Skeleton& s = c.skeleton;
  const int bone = limb.bones[2];
  const float Ll = s.length(limb.bones[1]), Lh = s.length(bone);
  const bool heel = c.contact == ContactMode::kFlat;
  MidJoint j;
  j.level = true;
  j.parent = j.child = bone;
  j.point_ls = heel ? glm::vec2(0.0f) : glm::vec2(Lh, 0.0f);
  const Mat2x3& rest = rig.rest[static_cast<size_t>(bone)];
  const glm::vec2 x(rest.m[0], rest.m[1]);
  j.rest_x = glm::length(x) > 1e-9f ? glm::normalize(x) : glm::vec2(1.0f, 0.0f);
  Mat2x3 bind = rest;
  const glm::vec2 at = rest.apply(j.point_ls);
  bind.m[4] = at.x;
  bind.m[5] = at.y;
  j.inverse_bind = inverse(bind);
  tube.contact_entry = rig.bone_count + static_cast<int>(rig.mid_joints.size());
  rig.mid_joints.push_back(j);
  tube.contact_point = at;
  if (heel) {
    tube.contact_inner = 1.2f * r_ankle;
    tube.contact_reach = std::min(3.0f * r_ankle, std::max(0.6f * Ll, tube.contact_inner));
    tube.contact_height = r_ankle;
  } else if (foot == Foot::kHoof) {
    tube.contact_inner = 0.3f * Lh;
    tube.contact_reach = 0.45f * Lh;
  } else {
    const float r = (foot == Foot::kPaw ? 1.3f : 1.0f) * r_toe;
    tube.contact_inner = std::min(1.5f * r, 0.4f * Lh);
    tube.contact_reach = std::min(3.5f * r, 0.6f * Lh);
  }
}

void plan_leg_or_arm(BodyRig& rig, const Limb& limb, int frames, BodyParts& plan) {
  const Creature& c = *rig.creature;
  const Skeleton& s = c.skeleton;
  const float B = rig.back_length;
  const float Lu = s.length(limb.bones[0]), Ll = s.length(limb.bones[1]), Lh = s.length(limb.bones[2]);
  if (!(Lu + Ll + Lh > 1e-5f)) return;
  const float wu = s.width(limb.bones[0]), wl = s.width(limb.bones[1]), wh = s.width(limb.bones[2]);
  const bool hind = limb.girdle == GirdleKind::kHip;
  const bool arm = limb.kind == LimbKind::kArm;
  const Foot foot = foot_of(rig, limb);
  // A bird's thigh and drumstick are feathered into the body's outline.
  const bool bird = foot == Foot::kBird;
  // Muscle at the girdle (thigh, shoulder), the knee and ankle thin (bony landmarks), the shin
  // thin, the foot by its kind.
  const float r_top = std::min((arm ? 0.2f : bird ? 0.4f : hind ? 0.32f : 0.26f) * Lu, (bird ? 0.3f : 0.22f) * B);
  // A bird's scaly tarsus and toes are thinner than the bone widths the skeleton draws.
  const float thin = bird ? 0.6f : 1.0f;
  const float r_knee = thin * (0.55f * std::max(wu, wl) + 0.02f * Lu);
  const float r_ankle = thin * (0.5f * std::max(wl, wh) * 0.9f + 0.01f * Ll);
  const float r_toe = foot == Foot::kBird ? 0.3f * wh : foot == Foot::kHoof ? 0.5f * wh : 0.42f * wh;
  const float radii[2] = {r_knee, r_ankle};
  LimbChain lc = limb_chain(rig, limb, frames, radii);
  const float s1 = lc.chain.start_s[1], s2 = lc.chain.start_s[2], s3 = lc.chain.start_s[3];
  const auto radius = [&](float s) -> std::array<float, 4> {
    float fixed, soft;
    if (s <= s1) {  // upper: muscle to the knee
      const float u = Lu > 0.0f ? s / Lu : 1.0f;
      const float r = r_top + (r_knee - r_top) * std::pow(u, 0.85f);
      fixed = std::min(0.5f * wu + 0.05f * std::max(r - 0.5f * wu, 0.0f), r);
      soft = r - fixed;
    } else if (s <= s2) {  // lower: the calf or forearm at its top, the shin thin below
      const float u = Ll > 0.0f ? (s - s1) / Ll : 1.0f;
      const float knee = bird ? std::max(1.15f * r_knee, 0.5f * r_top) : 1.15f * r_knee;
      // A bird's drumstick is feathered over its upper third, the rest bare and thin.
      const float r = knee + (r_ankle - knee) * (bird ? smooth01(0.1f, 0.45f, u) : std::pow(u, 0.6f));
      // The shin is bone and skin; the calf (a bird's drumstick) is muscle.
      fixed = std::min(thin * (0.5f * wl + 0.01f * Ll), r);
      soft = std::max(r - fixed, 0.0f);
    } else {  // hand or foot
      const float u = Lh > 0.0f ? (s - s2) / Lh : 1.0f;
      float r = r_ankle + (r_toe - r_ankle) * u;
      if (foot == Foot::kHoof) r *= 1.0f + 0.6f * smooth01(0.72f, 0.92f, u);
      if (foot == Foot::kPaw) r *= 1.0f + 0.3f * smooth01(0.6f, 0.9f, u);
      fixed = r;
      soft = 0.0f;
    }
    // The hind thigh's hamstrings bulge behind (top side on a downward chain), the front
    // upper arm's triceps too.
    const float back = s <= s1 ? 1.15f : 1.0f;
    return {fixed, soft * back, fixed, soft * (2.0f - back)};
  };
  TubePlan tube;
  tube.kind = arm ? BodyPartKind::kArm : BodyPartKind::kLeg;
  tube.layer = limb.side == Side::kNear ? Layer::kNear : Layer::kFar;
  tube.limb = static_cast<int>(&limb - c.limbs.data());
  tube.depth = 0.75f;
  tube.sections = sweep(lc, radius, 8);
  crease(lc, tube.sections);
  tube.start_cap = Cap::kRound;
  tube.end_cap = foot == Foot::kFlat || foot == Foot::kHand ? Cap::kRound : Cap::kPoint;
  tube.end_cap_length = foot == Foot::kFlat ? 0.8f : 0.55f;
  tube.fade_start = true;
  // The rest pose stays above the ground — for a leg, the level of its contact, where the
  // animator plants it: a flat foot's sole lies on its bone.
  const float ground = limb.kind != LimbKind::kLeg ? 0.0f
                       : c.contact == ContactMode::kFlat ? rig.bone_start(limb.bones[2]).y
                                                         : rig.bone_end(limb.bones[2]).y;
  for (Section& sec : tube.sections) sec.floor_y = ground;
  // A pointed end narrows to the contact at 30° or more either side: the last section sits
  // back from the tip by the radius / tan 30°... at most a third of the foot.
  if (tube.end_cap == Cap::kPoint && tube.sections.size() >= 3) {
    const std::array<float, 4> r_end = radius(s3);
    const float r = std::max(r_end[0], r_end[2]);
    const float back = std::min(r * 0.58f, 0.33f * Lh);
    const glm::vec2 tip = lc.chain.points.back();
    const glm::vec2 dir = rig.bone_dir(limb.bones[2]);
    Section last = tube.sections.back();
    // Every section within `back` of the tip gives way to one there and the tip.
    while (tube.sections.size() > 1 && tube.sections.back().s > s3 - back - 1e-6f) tube.sections.pop_back();
    Section before = last;
    before.s = s3 - back;
    before.centre = tip - dir * back;
    const std::array<float, 4> rb = radius(before.s);
    before.top_fixed = rb[0], before.top_soft = rb[1], before.bottom_fixed = rb[2], before.bottom_soft = rb[3];
    before.top_cap = before.bottom_cap = 1e30f;
    before.skin = chain_skin(lc.chain, lc.joints, before.s);
    last.centre = tip;
    last.top_fixed = last.bottom_fixed = last.top_soft = last.bottom_soft = 0.0f;
    tube.sections.push_back(before);
    tube.sections.push_back(last);
    // (Both keep the ground: Section::floor_y.)
  }
  if (limb.kind == LimbKind::kLeg && c.contact != ContactMode::kFlat) plant_contact(rig, limb, foot, r_ankle, r_toe, tube);
  // Hooves and claws in horn colour, a bird's scaly feet too (by the foot's length from the
  // ankle: u 0 at the ankle, 1 at the tip).
  for (Section& sec : tube.sections) {
    const float u = Lh > 0.0f ? (sec.s - s2) / Lh : 0.0f;
    if (foot == Foot::kHoof && u > 0.8f) sec.colour = hoof_colour();
    if (foot == Foot::kPaw && u > 0.9f) sec.colour = claw_colour();
    if (foot == Foot::kBird && u > 0.0f) sec.colour = scale_colour();
  }
  plan.tubes.push_back(std::move(tube));
}

// The convex hull of `pts` (counter-clockwise; Andrew's monotone chain).
std::vector<glm::vec2> convex_hull(std::vector<glm::vec2> pts) {
  std::sort(pts.begin(), pts.end(), [](glm::vec2 a, glm::vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  if (pts.size() < 3) return pts;
  const auto cross = [](glm::vec2 o, glm::vec2 a, glm::vec2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); };
  std::vector<glm::vec2> h(2 * pts.size());
  size_t k = 0;
  for (size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], pts[i]) <= 0.0f) --k;
    h[k++] = pts[i];
  }
  for (size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(h[k - 2], h[k - 1], pts[i]) <= 0.0f) --k;
    h[k++] = pts[i];
  }
  h.resize(k - 1);
  return h;
}

// The skin of a point near a limb: the bone whose segment is nearest.
Skin nearest_bone(const BodyRig& rig, const Limb& limb, glm::vec2 p) {
  float best = 1e30f;
  int bone = limb.bones[2];
  for (int b : limb.bones) {
    const glm::vec2 a = rig.bone_start(b), d = rig.bone_end(b) - a;
    const float len2 = glm::dot(d, d);
    const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, d) / len2, 0.0f, 1.0f) : 0.0f;
    const float dist = glm::length(a + t * d - p);
    if (dist < best) best = dist, bone = b;
  }
  return Skin::rigid(bone);
}

// A flat part around a limb: the convex hull of `pts`, each point on its nearest bone, none
// below `floor` in the rest pose.
FlatPlan hull_part(const BodyRig& rig, const Limb& limb, std::vector<glm::vec2> pts, float floor) {
  for (glm::vec2& p : pts) p.y = std::max(p.y, floor);
  FlatPlan f;
  f.outline = convex_hull(std::move(pts));
  glm::vec2 c(0.0f);
  for (const glm::vec2 p : f.outline) {
    c += p;
    f.skin.push_back(nearest_bone(rig, limb, p));
  }
  f.centre = f.outline.empty() ? c : c / static_cast<float>(f.outline.size());
  f.centre_skin = nearest_bone(rig, limb, f.centre);
  f.layer = limb.side == Side::kNear ? Layer::kNear : Layer::kFar;
  return f;
}

void plan_wing(const BodyRig& rig, const Limb& limb, BodyParts& plan) {
  const Creature& c = *rig.creature;
  const Skeleton& s = c.skeleton;
  const float Lh = s.length(limb.bones[2]);
  const glm::vec2 W = rig.bone_end(limb.bones[1]), T = rig.bone_end(limb.bones[2]);
  const glm::vec2 hand = rig.bone_dir(limb.bones[2]);
  const bool feathers = c.look.wings == WingCover::kFeathered;
  // Folded, the wing lies along the body's side as a lens from the wrist to the tips of the
  // primaries (past the hand; a membrane stops near it): its upper edge just over the hand,
  // its lower edge the secondaries' and coverts' curve below.
  const glm::vec2 tip = T + hand * ((feathers ? 0.75f : 0.1f) * Lh);
  const glm::vec2 axis = tip - W;
  const float len = glm::length(axis);
  if (!(len > 1e-6f)) return;
  const glm::vec2 along = axis / len;
  glm::vec2 down(along.y, -along.x);  // the side of the lens below the wing line
  if (down.y > 0.0f) down = -down;
  std::vector<glm::vec2> pts;
  for (int i = 0; i <= 10; ++i) {  // upper edge, wrist → tip
    const float t = static_cast<float>(i) / 10.0f;
    pts.push_back(W + axis * t - down * (0.07f * len * std::sin(3.1416f * std::pow(t, 0.7f))));
  }
  for (int i = 9; i >= 1; --i) {  // lower edge, tip → wrist
    const float t = static_cast<float>(i) / 10.0f;
    const float bulge = (feathers ? 0.3f : 0.24f) * len * std::sin(3.1416f * std::pow(t, 0.6f)) * (1.0f - 0.35f * t);
    pts.push_back(W + axis * t + down * bulge);
  }
  FlatPlan f;
  f.kind = BodyPartKind::kWing;
  f.layer = limb.side == Side::kNear ? Layer::kNear : Layer::kFar;
  const float floor = 0.004f * rig.back_length;
  for (glm::vec2& p : pts) p.y = std::max(p.y, floor);
  glm::vec2 centre(0.0f);
  for (const glm::vec2 p : pts) {
    f.skin.push_back(nearest_bone(rig, limb, p));
    centre += p;
  }
  f.outline = std::move(pts);
  f.centre = centre / static_cast<float>(f.outline.size());
  f.centre_skin = nearest_bone(rig, limb, f.centre);
  f.depth = 0.005f;  // feathers and membranes weigh little
  const glm::vec3 base = c.look.base;
  f.colour = feathers ? glm::vec4(glm::mix(base, c.look.pattern_colour, 0.35f), 1.0f) : glm::vec4(base * 0.72f, 0.93f);
  f.order = 2;
  plan.flats.push_back(std::move(f));
}

void plan_fin(const BodyRig& rig, const Limb& limb, BodyParts& plan) {
  const Creature& c = *rig.creature;
  const Skeleton& s = c.skeleton;
  const float L = s.length(limb.bones[0]) + s.length(limb.bones[1]) + s.length(limb.bones[2]);
  if (!(L > 1e-6f)) return;
  const glm::vec2 S = rig.bone_start(limb.bones[0]), T = rig.bone_end(limb.bones[2]);
  glm::vec2 d = T - S;
  d = glm::length(d) > 1e-9f ? glm::normalize(d) : glm::vec2(-1.0f, 0.0f);
  const glm::vec2 n(-d.y, d.x);
  // A fish's fin opens into a fan; a flipper (whales, seals, marine reptiles) is a paddle.
  const bool fan = c.skull_variant == 3;
  const float w0 = (fan ? 0.12f : 0.1f) * L, w1 = (fan ? 0.32f : 0.13f) * L;
  std::vector<glm::vec2> pts{S + n * w0, S - n * w0, T + n * w1, T - n * w1, T + d * (0.12f * L),
                             S + d * (0.6f * L) + n * (1.1f * w1), S + d * (0.6f * L) - n * (1.1f * w1)};
  float floor = 0.002f * rig.back_length;
  FlatPlan f = hull_part(rig, limb, std::move(pts), floor);
  f.kind = BodyPartKind::kFin;
  f.depth = fan ? 0.03f : 0.12f;
  f.colour = glm::vec4(c.look.base * (fan ? 0.85f : 0.9f), fan ? 0.88f : 1.0f);
  f.order = 2;
  plan.flats.push_back(std::move(f));
}

}  // namespace

void plan_limbs(BodyRig& rig, BodyParts& plan) {
  const Creature& c = *rig.creature;
  // Three mid-joint frames per knee and ankle while a creature's palette holds them (uint8
  // indices), else one, else none.
  // (Plus a contact frame per leg where there is room.)
  int joints = 0, legs = 0;
  for (const Limb& l : c.limbs) joints += l.kind == LimbKind::kLeg || l.kind == LimbKind::kArm ? 2 : 0;
  for (const Limb& l : c.limbs) legs += l.kind == LimbKind::kLeg;
  int frames = 3;
  while (frames > 0 && rig.bone_count + frames * joints + legs > 256) frames -= 2;
  for (const Limb& limb : c.limbs) {
    switch (limb.kind) {
      case LimbKind::kLeg:
      case LimbKind::kArm: plan_leg_or_arm(rig, limb, std::max(frames, 0), plan); break;
      case LimbKind::kWing: plan_wing(rig, limb, plan); break;
      case LimbKind::kFin: plan_fin(rig, limb, plan); break;
    }
  }
}

}  // namespace ossa::body
