#include "ossa/anim/anim_rig.h"

#include <algorithm>

#include "ossa/anim/anim_math.h"
#include "ossa/anim/foothold.h"
#include "ossa/anim/gait_family.h"
#include "ossa/anim/pentapedal.h"
#include "ossa/anim/secondary_motion.h"
#include "ossa/body/body_mesh.h"
#include "ossa/math/two_bone_ik.h"
#include "ossa/skeleton/pose.h"

namespace ossa {

namespace {

// A crouching leg steps up as high as a straight one this fraction of its reach long.
constexpr float kStepHeightOfReach = 0.8f;
// Lowest rest height of a girdle: a fraction of its leg's reach, and at least 1 mm.
constexpr float kMinRestHeightOfReach = 0.25f;
constexpr float kMinRestHeight = 0.001f;
// The wall sweep cuts the body into this many slabs along its length.
constexpr int kBodySlabs = 4;
// The trunk's drawn outline (AnimRig::flesh) is thinned to within this many hip heights.
constexpr float kFleshToleranceOfHip = 0.005f;
// AnimRig::crawl_climb: of the legless root's rest height, and of the body's length.
constexpr float kCrawlClimbOfRest = 2.0f, kCrawlClimbOfLength = 0.25f;

// The convex hull of points (Andrew's monotone chain), counter-clockwise.
std::vector<glm::vec2> convex_hull(std::vector<glm::vec2> p) {
  std::sort(p.begin(), p.end(), [](glm::vec2 a, glm::vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  if (p.size() < 3) return p;
  auto cross = [](glm::vec2 o, glm::vec2 a, glm::vec2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); };
  std::vector<glm::vec2> h(2 * p.size());
  size_t k = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0.0f) --k;
    h[k++] = p[i];
  }
  for (size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross(h[k - 2], h[k - 1], p[i - 1]) <= 0.0f) --k;
    h[k++] = p[i - 1];
  }
  h.resize(k - 1);
  return h;
}

RigLimb rig_limb(const RigLimbRole& limb) {
  RigLimb out;
  out.girdle_bone = limb.girdle_bone;
  out.bones = limb.bones;
  out.side = limb.side;
  return out;
}

// Can the legs hold the back off the ground? The back — the root, the back's vertebrae and
// what else hangs from them (ribs), not the neck, head, tail or a limb — must not reach below
// the ground the legs stand on in the rest pose (the lowest point of the legs and what hangs
// from them), by more than kBackBelowFeetOfReach of their mean reach (a bone of an imported
// armature lying at the ground does not count). Legs too short for their body (a random draw
// can hang a back of many metres on legs of a few decimetres) cannot: the body lies on its
// belly and crawls, the legs held as fins (AnimRig::legs_as_fins).
constexpr float kBackBelowFeetOfReach = 0.05f;

bool legs_hold_back_up(const Skeleton& sk, const std::vector<Mat2x3>& rest, const RigRoles& roles) {
  const int n = sk.bone_count();
  std::vector<uint8_t> other(n, 0), leg(n, 0);  // other: limbs, the neck, the skull and the tail
  float reach = 0.0f;
  int legs = 0;
  for (const RigLimbRole& limb : roles.limbs) {
    other[limb.bones[0]] = 1;
    if (limb.kind != LimbKind::kLeg) continue;
    leg[limb.bones[0]] = 1;
    reach += sk.length(limb.bones[0]) + sk.length(limb.bones[1]);
    ++legs;
  }
  if (legs == 0) return true;
  for (const std::vector<int>* chain : {&roles.neck, &roles.tail}) {
    for (int b : *chain) other[b] = 1;
  }
  if (roles.skull >= 0) other[roles.skull] = 1;
  float ground = 1e30f, back = 1e30f;
  for (int b = 0; b < n; ++b) {  // parents precede children
    if (sk.parent(b) >= 0) {
      other[b] |= other[sk.parent(b)];
      leg[b] |= leg[sk.parent(b)];
    }
    const float low = std::min(bone_start(rest[b]).y, bone_end(rest[b], sk.length(b)).y);
    if (leg[b]) ground = std::min(ground, low);
    if (!other[b]) back = std::min(back, low);
  }
  return back >= ground - kBackBelowFeetOfReach * reach / static_cast<float>(legs);
}

// A leg's thigh and shin place its foot: where the two together are shorter than this share
// of the foot (a random draw may give a limb of length-0 bones and a long foot), the foot can
// only turn about the girdle, it cannot stand while the body passes over it. Such a limb is no
// leg: it is carried as an arm, the body on its other legs, and the gait is chosen from those.
constexpr float kLegBonesOfFoot = 0.1f;

bool legs_without_reach_to_arms(const Skeleton& sk, RigRoles& roles) {
  bool any = false;
  for (RigLimbRole& limb : roles.limbs) {
    if (limb.kind != LimbKind::kLeg) continue;
    const float bones = sk.length(limb.bones[0]) + sk.length(limb.bones[1]);
    if (bones >= kLegBonesOfFoot * sk.length(limb.bones[2])) continue;
    limb.kind = LimbKind::kArm;
    any = true;
  }
  return any;
}

// A quadruped's foot at least this long against the leg above it (upper + lower) is a third
// segment of the leg (the examples' hooves and paws 0.5–0.79, the elephant's and the big
// dinosaurs' columnar feet 0.23–0.32; a shorter foot, brachiosaurus's hind 0.16, keeps rolling
// about its tip).
constexpr float kCoupledFootOfLeg = 0.2f;
// ... with upper and lower bones each at least this fraction of the two (a random leg may come
// with a vanishing bone: it keeps the plain solve).
constexpr float kCoupledBoneOfLeg = 0.05f;
// ... and with the foot standing at least this steep at rest (the sine of its angle to the
// ground). A foot the rest pose lays flat on the ground stands on its sole, as a plantigrade's
// does, and is drawn so (draw/sprite_choice.cpp, the same rule): stood on its tip in line with
// the forearm, the crouched forelegs of 10 of the 140 random tiptoe quadrupeds of seeds 1-400
// found no pose and folded the carpus to 5-95° all through the stance.
constexpr float kSteepFootAtRest = 0.5f;
// The lower joint's fold at mid-swing, chosen: the carpus 63°, at the low end of a horse's
// (about 70–100° in the swing of a walk and trot); the hind foot tucks by turning a further
// 23° from the thigh.
constexpr float kForeSwingFold = 1.1f;
constexpr float kHindSwingFold = 0.4f;
// A lower joint bent less than this at rest (radians) is taken to fold against the knee.
constexpr float kBentAnkle = 0.05f;

// Which legs are three-segment (RigLeg::coupled), and how their feet follow the leg.
void couple_legs(AnimRig& rig) {
  const std::vector<Mat2x3>& rest = rig.model_rest;
  // A biped's legs are not coupled: its thigh is held near level and moves little, the knee
  // and ankle do the walking (birds and theropods, Gatesy 1990, Paleobiology 16:170), so the
  // foot keeps its own angle (leg_ik.cpp bends the ankle no further than straight).
  const bool quadruped = rig.girdles.size() >= 2;
  for (RigLeg& leg : rig.legs) {
    leg.hind = leg.girdle + 1 == static_cast<int>(rig.girdles.size());
    leg.coupled = quadruped && !rig.flat_contact && leg.reach > 0.0f && leg.foot_length >= kCoupledFootOfLeg * leg.reach &&
                  std::min(leg.upper, leg.lower) >= kCoupledBoneOfLeg * leg.reach && std::fabs(leg.foot_dir_ms.y) >= kSteepFootAtRest;
    // The way the rest pose bends the lower joint (a zigzag leg: against the knee).
    const float rest_turn = wrap_angle(leg.foot_angle_ms - anim::bone_angle(rest[leg.bones[1]]));
    leg.fold_sign = std::fabs(rest_turn) > kBentAnkle ? (rest_turn > 0.0f ? 1.0f : -1.0f) : leg.bend;
    leg.rest_fold = std::fabs(rest_turn);
    leg.swing_fold = leg.hind ? kHindSwingFold : kForeSwingFold;
    // A hind foot's rest turn from the thigh (the hock bends and straightens with the knee).
    if (leg.hind) leg.couple_angle = wrap_angle(leg.foot_angle_ms - anim::bone_angle(rest[leg.bones[0]]));
    leg.couple_turn = {std::cos(leg.couple_angle), std::sin(leg.couple_angle)};
    const glm::vec2 pq(leg.upper + leg.foot_span * leg.couple_turn.x, leg.foot_span * leg.couple_turn.y);
    leg.couple_length = glm::length(pq);
    if (leg.couple_length > 0.0f) leg.couple_dir = pq / leg.couple_length;
  }
}

// Legs grouped by girdle slot, front girdle first.
void build_legs(const RigRoles& roles, AnimRig& rig) {
  const Skeleton& sk = rig.skeleton;
  const std::vector<Mat2x3>& rest = rig.model_rest;
  std::vector<int> slot_of_girdle;  // girdle_group of each girdle, in order of appearance
  for (const RigLimbRole& limb : roles.limbs) {
    if (limb.kind != LimbKind::kLeg) continue;
    RigLeg leg;
    leg.bones = limb.bones;
    leg.girdle_bone = limb.girdle_bone;
    leg.side = limb.side;
    leg.upper = sk.length(limb.bones[0]);
    leg.lower = sk.length(limb.bones[1]);
    leg.reach = leg.upper + leg.lower;
    leg.least_reach = std::fabs(leg.upper - leg.lower);
    // (A leg with a vanishing bone reaches only about its length: its stance stops there.)
    leg.leg_reach = std::max(kReachLimit * leg.reach, leg.least_reach);
    leg.fold = std::min(1.02f * leg.least_reach, leg.leg_reach);
    leg.bend = static_cast<float>(limb.bend_sign);
    leg.foot_length = sk.length(limb.bones[2]);
    const glm::vec2 joint = bone_start(rest[limb.bones[0]]);
    const glm::vec2 ankle = bone_end(rest[limb.bones[1]], sk.length(limb.bones[1]));
    const glm::vec2 tip = bone_end(rest[limb.bones[2]], sk.length(limb.bones[2]));
    leg.foot_angle_ms = rig.flat_contact ? 0.0f : anim::bone_angle(rest[limb.bones[2]]);
    leg.foot_offset_ms = rig.flat_contact ? glm::vec2(0.0f) : tip - ankle;
    leg.foot_dir_ms = {std::cos(leg.foot_angle_ms), std::sin(leg.foot_angle_ms)};
    leg.foot_span = glm::length(leg.foot_offset_ms);
    leg.contact_reach = leg.leg_reach + leg.foot_span;
    leg.contact_bone = rig.flat_contact ? limb.bones[1] : limb.bones[2];
    leg.ankle_rel_ms = -leg.foot_offset_ms;
    leg.tip_rel_ms = rig.flat_contact ? glm::vec2(leg.foot_length, 0.0f) : glm::vec2(0.0f);
    int group = -1;
    for (size_t g = 0; g < slot_of_girdle.size(); ++g) {
  if (slot_of_girdle[g] == limb.girdle_group) group = static_cast<int>(g);
    }
    if (group < 0) {
      group = static_cast<int>(rig.girdles.size());
      slot_of_girdle.push_back(limb.girdle_group);
      // A genome may pose a leg pointing up, leaving its girdle at or below the rest ground:
      // the girdle still stands a quarter of the leg's reach high (and never at zero height,
      // which every height-relative threshold divides or scales by).
      const float rest_height = std::max({joint.y, kMinRestHeightOfReach * leg.reach, kMinRestHeight});
      rig.girdles.push_back({joint, rest_height, rest_height, {}});
    }
    rig.girdles[group].legs.push_back(static_cast<int>(rig.legs.size()));
    leg.girdle = group;
    rig.legs.push_back(leg);
  }
  // Front (largest x) first; remap the legs' girdle indices.
  std::vector<int> order(rig.girdles.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return rig.girdles[a].joint_ms.x > rig.girdles[b].joint_ms.x; });
  std::vector<RigGirdle> sorted;
  for (int g : order) sorted.push_back(rig.girdles[g]);
  rig.girdles = sorted;
  for (size_t g = 0; g < rig.girdles.size(); ++g) {
    RigGirdle& girdle = rig.girdles[g];
    for (int leg : girdle.legs) {
      const RigLeg& info = rig.legs[leg];
      rig.legs[leg].girdle = static_cast<int>(g);
      girdle.step_height = std::max(girdle.step_height, kStepHeightOfReach * info.contact_reach);
      // Standing, which way does the knee point?
      if (knee_ahead(info, girdle.rest_height) > 0.0f) girdle.knee_reach = std::max(girdle.knee_reach, info.upper);
    }
  }
  couple_legs(rig);
  rig.climb_height = 0.0f;
  for (size_t g = 0; g < rig.girdles.size(); ++g) {
    rig.climb_height = g == 0 ? rig.girdles[g].step_height : std::min(rig.climb_height, rig.girdles[g].step_height);
  }
  for (const RigLeg& leg : rig.legs) {
    rig.longest_foot_reach = std::max(rig.longest_foot_reach, leg.foot_span + 0.05f);
  }
  rig.longest_contact_reach = rig.longest_foot_reach;
  for (const RigLeg& leg : rig.legs) rig.longest_contact_reach = std::max(rig.longest_contact_reach, leg.contact_reach);
}

// One of each left/right pair whose rest poses coincide in the side view.
std::vector<RigLimb> distinct_outlines(const AnimRig& rig, const std::vector<RigLimb>& limbs) {
  const Skeleton& sk = rig.skeleton;
  std::vector<RigLimb> out;
  for (const RigLimb& a : limbs) {
    auto same = [&](const RigLimb& b) {
      for (size_t k = 0; k < a.bones.size(); ++k) {
        const int i = a.bones[k], j = b.bones[k];
        if (bone_start(rig.model_rest[i]) != bone_start(rig.model_rest[j]) ||
            bone_end(rig.model_rest[i], sk.length(i)) != bone_end(rig.model_rest[j], sk.length(j))) {
          return false;
        }
      }
      return true;
    };
    if (std::none_of(out.begin(), out.end(), same)) out.push_back(a);
  }
  return out;
}

// The wall sweep's outline of a rigid body in slabs along it (a pitched body's single box
// would meet the stairs it climbs): the spine's segments relative to the root's frame,
// clipped to each slab, reduced to their hull.
void build_body_outline(AnimRig& rig, const Mat2x3& root_inv) {
  const Skeleton& sk = rig.skeleton;
  std::vector<int> body = {rig.root};
  body.insert(body.end(), rig.back.begin(), rig.back.end());
  body.insert(body.end(), rig.neck.begin(), rig.neck.end());
  std::vector<std::pair<glm::vec2, glm::vec2>> segments;
  float x0 = 1e30f, x1 = -1e30f;
  for (int b : body) {
    const glm::vec2 p = root_inv.apply(bone_start(rig.model_rest[b])), q = root_inv.apply(bone_end(rig.model_rest[b], sk.length(b)));
    segments.push_back({p, q});
    x0 = std::min({x0, p.x, q.x});
    x1 = std::max({x1, p.x, q.x});
  }
  for (int k = 0; k < kBodySlabs; ++k) {
    const float a = x0 + (x1 - x0) * static_cast<float>(k) / kBodySlabs;
    const float b = x0 + (x1 - x0) * static_cast<float>(k + 1) / kBodySlabs;
    std::vector<glm::vec2> points;
    for (const auto& segment : segments) {
      glm::vec2 p = segment.first, q = segment.second;  // (clang 14 lambdas cannot capture bindings)
      if (p.x > q.x) std::swap(p, q);
      if (q.x < a || p.x > b) continue;
      auto at = [&](float x) { return q.x - p.x < 1e-9f ? p : p + (q - p) * ((x - p.x) / (q.x - p.x)); };
      points.push_back(p.x < a ? at(a) : p);
      points.push_back(q.x > b ? at(b) : q);
    }
    if (!points.empty()) rig.body_slabs.push_back(convex_hull(points));
  }
  for (const std::vector<glm::vec2>& slab : rig.body_slabs) rig.body_hull.insert(rig.body_hull.end(), slab.begin(), slab.end());
  rig.body_hull = convex_hull(rig.body_hull);
  if (rig.skull >= 0) {
    const Mat2x3& skull = rig.model_rest[rig.skull];
    rig.skull_rel = root_inv.apply(bone_start(skull));
    rig.skull_span = bone_end(skull, sk.length(rig.skull)) - bone_start(skull);
  }
  rig.body_lo = rig.body_hi = rig.body_hull[0];
  for (glm::vec2 p : rig.body_hull) {
    rig.body_lo = glm::min(rig.body_lo, p);
    rig.body_hi = glm::max(rig.body_hi, p);
  }
  if (rig.skull >= 0) {
    rig.body_lo = glm::min(rig.body_lo, rig.skull_rel);
    rig.body_hi = glm::max(rig.body_hi, rig.skull_rel);
  }
}

// The flesh (roles.flesh) about each of `bones`, in its frame at rest: x along the bone, y
// across; a bone without flesh of its own, the bone. Empty when none of them has flesh.
std::vector<Box> flesh_about(const AnimRig& rig, const RigRoles& roles, const std::vector<int>& bones) {
  bool any = false;
  std::vector<Box> flesh(bones.size(), Box{glm::vec2(1e30f), glm::vec2(-1e30f)});
  for (const RigRoles::FleshPoint& f : roles.flesh) {
    const auto at = std::find(bones.begin(), bones.end(), f.bone);
    if (at == bones.end()) continue;
    const glm::vec2 q = inverse(rig.model_rest[f.bone]).apply(f.position_ms);
    Box& box = flesh[static_cast<size_t>(at - bones.begin())];
    box = box.united(Box{q, q});
    any = true;
  }
  if (!any) return {};
  for (size_t k = 0; k < bones.size(); ++k) flesh[k] = flesh[k].united(Box{glm::vec2(0.0f), glm::vec2(rig.skeleton.length(bones[k]), 0.0f)});
  return flesh;
}

// The tail's flesh about each tail bone (AnimRig::tail_flesh).
void build_tail_flesh(AnimRig& rig, const RigRoles& roles) {
  rig.tail_flesh = flesh_about(rig, roles, rig.tail);
  rig.tail_reach = rig.tail_length;
  for (size_t k = 0; k < rig.tail_flesh.size(); ++k) {
    const float len = rig.skeleton.length(rig.tail[k]);
    const Box& f = rig.tail_flesh[k];
    rig.tail_reach = std::max(rig.tail_reach, rig.tail_length + std::max({-f.min_ws.y, f.max_ws.y, -f.min_ws.x, f.max_ws.x - len}));
  }
}

// A legless body's flesh about the bones its wall sweep takes (AnimRig::crawl_flesh).
void build_crawl_flesh(AnimRig& rig, const RigRoles& roles) {
  rig.crawl_bones = {rig.root};
  rig.crawl_bones.insert(rig.crawl_bones.end(), rig.back.begin(), rig.back.end());
  rig.crawl_bones.insert(rig.crawl_bones.end(), rig.neck.begin(), rig.neck.end());
  if (rig.skull >= 0) rig.crawl_bones.push_back(rig.skull);
  rig.crawl_flesh = flesh_about(rig, roles, rig.crawl_bones);
  if (rig.crawl_flesh.empty()) rig.crawl_bones.clear();
}

// The outline of a limb's own part (the one with most points on its bones), point by point
// (RigLeg::flesh_outline), each skinned as the body skins it:
// its weights on the limb's bones and on the mid joints between them (knee, ankle, the foot's
// level frame: *mids, their parent and child the limb's bone slots). Weight on other frames
// (the girdle's) is left out; a point that follows them more than the limb is left out
// whole, its neighbours span the gap. *margin: per bone, the farthest a point lies from it in
// a frame on it (a mid joint's: from the joint; the level frame's: from the foot). Thinned
// evenly to at most kLimbFleshPoints.
std::vector<LimbFleshPoint> limb_flesh(const AnimRig& rig, const RigRoles& roles, const std::array<int, 3>& bones,
                                       std::array<float, 3>* margin, std::vector<MidJoint>* mids) {
  auto bone_of = [&](int bone) { return static_cast<int>(std::find(bones.begin(), bones.end(), bone) - bones.begin()); };
  mids->clear();
  std::vector<int> on_limb;
  for (const RigRoles::FleshPoint& f : roles.flesh) {
    if (bone_of(f.bone) >= 3) continue;
    if (on_limb.size() <= static_cast<size_t>(f.part)) on_limb.resize(static_cast<size_t>(f.part) + 1, 0);
    ++on_limb[static_cast<size_t>(f.part)];
  }
  if (on_limb.empty()) return {};
  const int own = static_cast<int>(std::max_element(on_limb.begin(), on_limb.end()) - on_limb.begin());
  const int bone_count = rig.skeleton.bone_count();
  // The skin frame of palette entry e on this limb (-1: none of the limb's), its mid joint
  // taken into *mids the first time.
  std::vector<int> frame_of_entry(static_cast<size_t>(bone_count) + roles.mid_joints.size(), -2);
  auto frame_of = [&](int e) {
    if (static_cast<size_t>(e) >= frame_of_entry.size()) return -1;
    int& f = frame_of_entry[static_cast<size_t>(e)];
    if (f != -2) return f;
    f = -1;
    if (e < bone_count) {
      const int k = bone_of(e);
      if (k < 3) f = k;
      return f;
    }
    MidJoint j = roles.mid_joints[static_cast<size_t>(e - bone_count)];
    const int parent = bone_of(j.parent), child = bone_of(j.child);
    if (parent < 3 && child < 3 && mids->size() < kLimbMidFrames) {
      j.parent = parent;
      j.child = child;
      f = 3 + static_cast<int>(mids->size());
      mids->push_back(j);
    }
    return f;
  };
  std::vector<LimbFleshPoint> outline;
  for (const RigRoles::FleshPoint& f : roles.flesh) {
    if (f.part != own) continue;
    LimbFleshPoint q;
    float total = 0.0f;
    for (size_t i = 0; i < 4; ++i) {
      if (!(f.weights[i] > 0.0f)) continue;
      const int frame = frame_of(f.entries[i]);
      if (frame < 0) continue;
      const size_t c = static_cast<size_t>(q.count++);
      q.frame[c] = static_cast<uint8_t>(frame);
      q.weight[c] = f.weights[i];
      total += f.weights[i];
      int k;  // the bone the frame lies on
      float off;
      if (frame < 3) {
        k = frame;
        q.local[c] = inverse(rig.model_rest[bones[static_cast<size_t>(k)]]).apply(f.position_ms);
        off = glm::length(q.local[c] - glm::vec2(std::clamp(q.local[c].x, 0.0f, rig.skeleton.length(bones[static_cast<size_t>(k)])), 0.0f));
      } else {
        const MidJoint& j = (*mids)[static_cast<size_t>(frame - 3)];
        k = j.child;
        q.local[c] = j.inverse_bind.apply(f.position_ms);
        off = glm::length(q.local[c]);
      }
      float& m = (*margin)[static_cast<size_t>(k)];
      m = std::max(m, off);
    }
    if (!(total >= 0.5f)) continue;
    for (int i = 0; i < q.count; ++i) q.weight[static_cast<size_t>(i)] /= total;
    outline.push_back(q);
  }
  const size_t n = outline.size(), kept = std::min(n, kLimbFleshPoints);
  std::vector<LimbFleshPoint> thinned;
  for (size_t i = 0; i < kept; ++i) thinned.push_back(outline[i * n / kept]);
  return thinned;
}

// Each leg's flesh about its foot (RigLeg::flesh_back/flesh_front): the outline of every part
// with a point on the leg's bones (its own part: a near and a far leg each have one). And the
// leg's drawn outline above the sole, on its bones (RigLeg::flesh_outline).
void build_foot_flesh(AnimRig& rig, const RigRoles& roles) {
  for (RigLeg& leg : rig.legs) {
    const glm::vec2 contact = bone_end(rig.model_rest[leg.contact_bone], rig.skeleton.length(leg.contact_bone));
    const float height = anim::foot_height(rig.scale, leg);
    float lo = 0.0f, hi = 0.0f;
    for (size_t begin = 0; begin < roles.flesh.size();) {
      size_t end = begin;
      bool ours = false;
      while (end < roles.flesh.size() && roles.flesh[end].part == roles.flesh[begin].part) {
        ours = ours || std::find(leg.bones.begin(), leg.bones.end(), roles.flesh[end].bone) != leg.bones.end();
        ++end;
      }
      for (size_t i = begin; ours && i < end; ++i) {
        const glm::vec2 p = roles.flesh[i].position_ms - contact;
        if (p.y > height) continue;
        lo = std::min(lo, p.x);
        hi = std::max(hi, p.x);
      }
      begin = end;
    }
    const anim::FootSpan span = anim::foot_span_ws(leg, 1);
    leg.flesh_back = std::max(0.0f, span.lo - lo);
    leg.flesh_front = std::max(0.0f, hi - span.hi);
    leg.flesh_outline = limb_flesh(rig, roles, leg.bones, &leg.flesh_margin, &leg.flesh_mids);
  }
}

// Which part of the trunk each bone is: the body's (the spine but the tail, the ribs), the
// head's (the skull and what hangs from it) or neither (a limb's, the tail's).
enum class TrunkPart : uint8_t { kBody, kHead, kNone };
std::vector<TrunkPart> trunk_parts(const AnimRig& rig) {
  const Skeleton& sk = rig.skeleton;
  std::vector<uint8_t> tail(sk.bone_count(), 0), skull(sk.bone_count(), 0);
  for (int b : rig.tail) tail[b] = 1;
  if (rig.skull >= 0) skull[rig.skull] = 1;
  for (int b = 0; b < sk.bone_count(); ++b) {  // parents precede children
    if (sk.parent(b) < 0) continue;
    tail[b] |= tail[sk.parent(b)];
    skull[b] |= skull[sk.parent(b)];
  }
  std::vector<TrunkPart> part(sk.bone_count(), TrunkPart::kNone);
  for (int b = 0; b < sk.bone_count(); ++b) {
    if (!rig.limb_bone[b] && !tail[b]) part[b] = skull[b] ? TrunkPart::kHead : TrunkPart::kBody;
  }
  return part;
}

// The trunk's segments (AnimRig::trunk): every bone neither a limb's nor the tail's, the
// skull's and what hangs from it last.
void build_trunk(AnimRig& rig) {
  if (rig.legs.empty()) return;
  const Skeleton& sk = rig.skeleton;
  const std::vector<TrunkPart> parts = trunk_parts(rig);
  std::vector<AnimRig::TrunkSegment> body, head;
  auto add = [&](std::vector<AnimRig::TrunkSegment>& to, int b) {
    const AnimRig::TrunkSegment seg{bone_start(rig.model_rest[b]), bone_end(rig.model_rest[b], sk.length(b))};
    if (glm::distance(seg.a, seg.b) < 1e-4f * rig.body_half_length) return;
    for (const AnimRig::TrunkSegment& t : to) {
      if (glm::distance(t.a, seg.a) + glm::distance(t.b, seg.b) < 1e-5f * rig.body_half_length) return;
    }
    to.push_back(seg);
  };
  for (int b = 0; b < sk.bone_count(); ++b) {
    if (parts[b] != TrunkPart::kNone) add(parts[b] == TrunkPart::kHead ? head : body, b);
  }
  rig.trunk = body;
  rig.trunk_level_from = body.size();
  rig.trunk.insert(rig.trunk.end(), head.begin(), head.end());
  const glm::vec2 root{0.0f, rig.root_rest_y};
  rig.trunk_lo = glm::vec2(1e30f);
  rig.trunk_hi = glm::vec2(-1e30f);
  for (const AnimRig::TrunkSegment& t : rig.trunk) {
    rig.trunk_lo = glm::min(rig.trunk_lo, glm::min(t.a, t.b) - root);
    rig.trunk_hi = glm::max(rig.trunk_hi, glm::max(t.a, t.b) - root);
  }
}

// Points of an open polyline kept by Douglas–Peucker: every point dropped lies within `tol`
// of the chord between the kept ones around it.
void thin_polyline(const std::vector<glm::vec2>& p, size_t from, size_t to, float tol, std::vector<glm::vec2>& kept) {
  float worst = tol;
  size_t at = 0;
  const glm::vec2 a = p[from], d = p[to] - a;
  const float len = glm::length(d);
  for (size_t i = from + 1; i < to; ++i) {
    const glm::vec2 v = p[i] - a;
    const float off = len > 1e-9f ? std::fabs(v.x * d.y - v.y * d.x) / len : glm::length(v);
    if (off > worst) worst = off, at = i;
  }
  if (at == 0) {
    kept.push_back(p[to]);
    return;
  }
  thin_polyline(p, from, at, tol, kept);
  thin_polyline(p, at, to, tol, kept);
}

// The drawn body's outline about the trunk (AnimRig::flesh): each part's closed outline cut
// into runs of points that follow the body's bones or the head's, each run thinned to within
// kFleshToleranceOfHip.
void build_flesh(AnimRig& rig, const RigRoles& roles) {
  if (rig.legs.empty() || roles.flesh.empty()) return;
  const std::vector<TrunkPart> parts = trunk_parts(rig);
  const float tol = kFleshToleranceOfHip * rig.hip_height;
  auto part_of = [&](const RigRoles::FleshPoint& f) {
    return f.bone >= 0 && f.bone < static_cast<int>(parts.size()) ? parts[static_cast<size_t>(f.bone)] : TrunkPart::kNone;
  };
  std::vector<AnimRig::TrunkSegment> body, head;
  std::vector<glm::vec2> run, kept;
  auto flush = [&](TrunkPart part) {
    if (run.size() >= 2 && part != TrunkPart::kNone) {
      kept.assign(1, run[0]);
      thin_polyline(run, 0, run.size() - 1, tol, kept);
      std::vector<AnimRig::TrunkSegment>& to = part == TrunkPart::kHead ? head : body;
      for (size_t i = 1; i < kept.size(); ++i) to.push_back({kept[i - 1], kept[i]});
    }
    run.clear();
  };
  for (size_t begin = 0; begin < roles.flesh.size();) {
    size_t end = begin;
    while (end < roles.flesh.size() && roles.flesh[end].part == roles.flesh[begin].part) ++end;
    // The closed outline from a point where its part changes (or from its first point), round
    // to that point again.
    const size_t n = end - begin;
    size_t start = 0;
    for (size_t i = 0; i < n; ++i) {
      if (part_of(roles.flesh[begin + i]) != part_of(roles.flesh[begin + (i + n - 1) % n])) {
        start = i;
        break;
      }
    }
    TrunkPart current = part_of(roles.flesh[begin + start]);
    for (size_t k = 0; k <= n; ++k) {
      const RigRoles::FleshPoint& f = roles.flesh[begin + (start + k) % n];
      const TrunkPart part = part_of(f);
      if (part != current) {
        flush(current);
        current = part;
      }
      run.push_back(f.position_ms);
    }
    flush(current);
    begin = end;
  }
  rig.flesh = body;
  rig.flesh_level_from = body.size();
  rig.flesh.insert(rig.flesh.end(), head.begin(), head.end());
  const glm::vec2 root{0.0f, rig.root_rest_y};
  const glm::vec2 skull = rig.skull >= 0 ? bone_start(rig.model_rest[rig.skull]) : glm::vec2(0.0f);
  rig.flesh_lo = rig.head_flesh_lo = glm::vec2(1e30f);
  rig.flesh_hi = rig.head_flesh_hi = glm::vec2(-1e30f);
  for (size_t i = 0; i < rig.flesh.size(); ++i) {
    const AnimRig::TrunkSegment& t = rig.flesh[i];
    const bool level = i >= rig.flesh_level_from;
    glm::vec2& lo = level ? rig.head_flesh_lo : rig.flesh_lo;
    glm::vec2& hi = level ? rig.head_flesh_hi : rig.flesh_hi;
    const glm::vec2 from = level ? skull : root;
    lo = glm::min(lo, glm::min(t.a, t.b) - from);
    hi = glm::max(hi, glm::max(t.a, t.b) - from);
  }
}

// A legless body's drape (AnimRig::drape_bones): which spine bone each ends at, and the depth of
// what hangs below each joint, at rest.
void build_drape(const RigRoles& roles, AnimRig& rig) {
  const Skeleton& sk = rig.skeleton;
  const int n = sk.bone_count();
  const std::vector<uint8_t>& limb = rig.limb_bone;  // (build_fk_plan's, every limb bone)
  std::vector<uint8_t> spine(n, 0);
  for (const std::vector<int>* chain : {&rig.back, &rig.neck, &rig.tail}) {
    for (int b : *chain) spine[b] = 1;
  }
  spine[rig.root] = 1;  // (the skull is not: it hangs from the neck, kept level)
  // The spine bone each bone hangs from (itself for a spine bone; −1 for a limb's).
  std::vector<int> owner(n, -1), next(n, -1);
  for (int b = 0; b < n; ++b) {  // parents precede children
    const int p = sk.parent(b);
    if (spine[b]) {
      owner[b] = b;
      if (p >= 0 && spine[p] && p != rig.root) next[p] = b;
    } else if (!limb[b] && p >= 0) {
      owner[b] = owner[p];
    }
  }
  // The skull and what hangs from it are placed as the head (drape_legless), not as the
  // neck's hangers: their points are the skull's own (skull_hang_points).
  std::vector<uint8_t> in_head(n, 0);
  for (int b = 0; b < n; ++b) in_head[b] = b == rig.skull || (sk.parent(b) >= 0 && in_head[sk.parent(b)] && !limb[b]);
  rig.belly.assign(n, 0.0f);
  std::vector<float> lowest(n, 1e30f);  // per spine bone: the lowest rest point hanging from it
  for (int b = 0; b < n; ++b) {
    if (owner[b] < 0 || owner[b] == b) continue;
    const float y = std::min(bone_start(rig.model_rest[b]).y, bone_end(rig.model_rest[b], sk.length(b)).y);
    lowest[owner[b]] = std::min(lowest[owner[b]], y);
  }
  // A limb's root hangs from the spine too (the limb itself keeps out of the ground on its own).
  std::vector<std::pair<int, glm::vec2>> roots;  // (spine owner, the root at rest)
  for (const RigLimbRole& l : roles.limbs) {
    const int o = l.girdle_bone >= 0 ? owner[l.girdle_bone] : -1;
    if (o < 0) continue;
    roots.emplace_back(o, bone_start(rig.model_rest[l.bones[0]]));
    lowest[o] = std::min(lowest[o], roots.back().second.y);
  }
  for (int b = 0; b < n; ++b) {
    if (!spine[b]) continue;
    const float joint = bone_start(rig.model_rest[b]).y;
    rig.belly[b] = std::max(0.5f * sk.width(b), lowest[b] < 1e29f ? joint - lowest[b] : 0.0f);
  }
  for (int b = 0; b < n; ++b) {
    if (!spine[b] || b == rig.root) continue;
    rig.drape_bones.push_back(b);
    rig.drape_next.push_back(next[b]);
    const glm::vec2 v = next[b] >= 0 ? rig.rest_pose.locals[next[b]].offset_ls : glm::vec2(sk.length(b), 0.0f);
    rig.drape_length.push_back(glm::length(v));
    rig.drape_along.push_back(std::atan2(v.y, v.x));
    const float end = bone_end(rig.model_rest[b], sk.length(b)).y;
    rig.tip_belly.push_back(std::max(0.5f * sk.width(b), lowest[b] < 1e29f ? end - lowest[b] : 0.0f));
    rig.hang_begin.push_back(static_cast<int>(rig.hang_points.size()));
    const Mat2x3 to_bone = inverse(rig.model_rest[b]);
    for (const auto& [o, p] : roots) {
      if (o == b) rig.hang_points.push_back(to_bone.apply(p));
    }
    rig.hang_pairs.push_back(static_cast<int>(rig.hang_points.size()));
    for (int h = 0; h < n; ++h) {
      if (owner[h] != b || h == b || in_head[h]) continue;
      rig.hang_points.push_back(to_bone.apply(bone_start(rig.model_rest[h])));
      rig.hang_points.push_back(to_bone.apply(bone_end(rig.model_rest[h], sk.length(h))));
    }
  }
  rig.hang_begin.push_back(static_cast<int>(rig.hang_points.size()));
  const Mat2x3 to_root = inverse(rig.model_rest[rig.root]);
  for (const auto& [o, p] : roots) {
    if (o == rig.root) rig.root_hang_points.push_back(to_root.apply(p));
  }
  rig.root_hang_pairs = static_cast<int>(rig.root_hang_points.size());
  for (int h = 0; h < n; ++h) {
    if (owner[h] != rig.root || h == rig.root) continue;
    rig.root_hang_points.push_back(to_root.apply(bone_start(rig.model_rest[h])));
    rig.root_hang_points.push_back(to_root.apply(bone_end(rig.model_rest[h], sk.length(h))));
  }
  if (rig.skull >= 0) {
    const Mat2x3 to_skull = inverse(rig.model_rest[rig.skull]);
    for (int h = 0; h < n; ++h) {
      if (!in_head[h] || h == rig.skull) continue;
      rig.skull_hang_points.push_back(to_skull.apply(bone_start(rig.model_rest[h])));
      rig.skull_hang_points.push_back(to_skull.apply(bone_end(rig.model_rest[h], sk.length(h))));
    }
  }
  std::vector<uint8_t> placed(n, 0);
  for (int b = 0; b < n; ++b) placed[b] = spine[b] || b == rig.skull;
  for (const RigLimbRole& l : roles.limbs) {
    for (int b = l.girdle_bone; b >= 0 && !placed[b]; b = sk.parent(b)) placed[b] = 1;
  }
  for (int b = 0; b < n; ++b) {
    if (placed[b]) {
      for (int a = sk.parent(b); a >= 0 && !placed[a]; a = sk.parent(a)) placed[a] = 1;
    }
  }
  for (int b = 0; b < n; ++b) {
    if (placed[b]) rig.drape_fk.push_back(b);
  }
  if (rig.skull >= 0) {
    rig.head_owner = owner[rig.skull];
    rig.skull_rest_angle = std::atan2(rig.model_rest[rig.skull].m[1], rig.model_rest[rig.skull].m[0]);
  }
  // The root rests (root_rest_y) as high as the joints around it need, each no steeper than the
  // drape lays a bone (kDrapeSlope, secondary_motion.cpp): a small root bone may carry no ribs
  // of its own, and a deep head far ahead needs the body to rise towards it. (The hip height,
  // and so the speeds, keep the rest pose's root height: it was taken before.)
  rig.root_rest_y = rig.belly[rig.root];
  const glm::vec2 root_at = bone_start(rig.model_rest[rig.root]);
  for (int b = 0; b < n; ++b) {
    if (!spine[b]) continue;
    const glm::vec2 at = bone_start(rig.model_rest[b]);
    const float run = std::fabs(at.x - root_at.x);
    rig.root_rest_y = std::max(rig.root_rest_y, rig.belly[b] - anim::kDrapeSlope * run);
  }
  for (size_t i = 0; i < rig.drape_bones.size(); ++i) {
    if (rig.drape_next[i] >= 0) continue;
    const int b = rig.drape_bones[i];
    const float run = std::fabs(bone_end(rig.model_rest[b], sk.length(b)).x - root_at.x);
    rig.root_rest_y = std::max(rig.root_rest_y, rig.tip_belly[i] - anim::kDrapeSlope * run);
  }
}

// Which bones each tick keeps current and how: the root, the girdles (rigid to the root: one
// product each, skipping the vertebrae between) and the limb chains; the rest on demand.
void build_fk_plan(const RigRoles& roles, AnimRig& rig) {
  const Skeleton& sk = rig.skeleton;
  const int root = rig.root;
  rig.rest_local_m.resize(sk.bone_count());
  for (int b = 0; b < sk.bone_count(); ++b) rig.rest_local_m[b] = local_matrix(rig.rest_pose.locals[b]);
  rig.dynamic_bone.assign(sk.bone_count(), rig.legs.empty() ? 1 : 0);  // legless bodies bend all along
  rig.dynamic_bone[root] = 1;
  if (rig.skull >= 0) rig.dynamic_bone[rig.skull] = 1;
  for (int b : rig.tail) rig.dynamic_bone[b] = 1;
  std::vector<uint8_t> limb_bone(sk.bone_count(), 0);
  for (const RigLimbRole& limb : roles.limbs) {
    for (int b : limb.bones) limb_bone[b] = 1;
  }
  std::vector<uint8_t> leg_ik_bone(sk.bone_count(), 0);
  for (const RigLeg& leg : rig.legs) {
    for (int b : leg.bones) leg_ik_bone[b] = 1;
  }
  for (int b = 0; b < sk.bone_count(); ++b) {
    if (limb_bone[b] && !leg_ik_bone[b]) rig.other_limb_bones.push_back(b);
  }
  rig.limb_bone = limb_bone;
  for (int b = 0; b < sk.bone_count(); ++b) {  // parents precede children
    if (sk.parent(b) >= 0 && rig.limb_bone[sk.parent(b)]) rig.limb_bone[b] = 1;
  }
  // Girdles are rigid to the root unless a bone between bends (legless bodies).
  bool rigid = sk.parent(root) < 0 && !rig.legs.empty();
  std::vector<uint8_t> needed(sk.bone_count(), 0), girdle(sk.bone_count(), 0);
  for (const RigLimbRole& limb : roles.limbs) {
    girdle[limb.girdle_bone] = 1;
    for (int b = limb.girdle_bone; b >= 0; b = sk.parent(b)) {
      needed[b] = 1;
      if (b != root && rig.dynamic_bone[b]) rigid = false;
      if (sk.parent(b) < 0 && b != root) rigid = false;
    }
  }
  needed[root] = 1;
  rig.tick_bone = limb_bone;
  if (rigid) {
    const Mat2x3 root_inv = inverse(rig.model_rest[root]);
    rig.needed_bones = {root};
    rig.tick_bone[root] = 1;
    for (int b = 0; b < sk.bone_count(); ++b) {
      if (!girdle[b] || b == root) continue;
      rig.girdle_bones.push_back(b);
      rig.girdle_rel.push_back(root_inv * rig.model_rest[b]);
      rig.tick_bone[b] = 1;
    }
    for (RigLeg& leg : rig.legs) leg.girdle_rel_angle = anim::bone_angle(root_inv * rig.model_rest[leg.girdle_bone]);
    build_body_outline(rig, root_inv);
  } else {
    // The neck and head take part in the wall sweep.
    for (int b : rig.neck) needed[b] = 1;
    if (rig.skull >= 0) needed[rig.skull] = 1;
    for (int b = 0; b < sk.bone_count(); ++b) {
      if (!needed[b]) continue;
      rig.needed_bones.push_back(b);
      rig.tick_bone[b] = 1;
    }
  }
  if (!rig.tail.empty()) {
    std::vector<int> between;
    int b = sk.parent(rig.tail[0]);
    while (b >= 0 && !rig.tick_bone[b]) {
      between.push_back(b);
      b = sk.parent(b);
    }
    if (b >= 0) {
      rig.tail_base_bone = b;
      rig.tail_between.assign(between.rbegin(), between.rend());
      for (int t : rig.tail) rig.tail_length += sk.length(t);
      build_tail_flesh(rig, roles);
      bool rest = true;
      for (int t : rig.tail_between) rest = rest && !rig.dynamic_bone[t];
      if (rest) {
        for (int t : rig.tail_between) rig.tail_between_rest = rig.tail_between_rest * rig.rest_local_m[t];
        rig.tail_between.clear();
      }
    }
  }
  // The neck's base turns for the head's nod and head-bob (head_motion, trunk_bob.h) when the
  // skull hangs from it and no girdle does.
  if (!rig.legs.empty() && !rig.neck.empty() && rig.skull >= 0 && !needed[rig.neck.back()]) {
    const int base = rig.neck.back();
    bool carries_skull = false;
    for (int b = rig.skull; b >= 0; b = sk.parent(b)) carries_skull = carries_skull || b == base;
    if (carries_skull) {
      // The head is kept level, so its far end moves as its joint does. The second joint is
      // the one nearest halfway up the neck (the two parts then reach furthest as two bones).
      const glm::vec2 head = bone_start(rig.model_rest[rig.skull]);
      auto reach = [&](int b) { return head - bone_start(rig.model_rest[b]); };
      const float half = 0.5f * glm::length(reach(base));
      float best = 1e30f;
      for (size_t i = 0; i + 1 < rig.neck.size(); ++i) {
        const float off = std::fabs(glm::length(reach(rig.neck[i])) - half);
        if (off < best) best = off, rig.nod_bones[1] = rig.neck[i];
      }
      rig.nod_bones[0] = base;
      for (size_t i = 0; i < 2; ++i) {
        if (rig.nod_bones[i] < 0) continue;
        rig.dynamic_bone[rig.nod_bones[i]] = 1;
        rig.nod_reach[i] = reach(rig.nod_bones[i]);
      }
      std::vector<char> under(static_cast<size_t>(sk.bone_count()), 0);
      for (int b = base; b < sk.bone_count(); ++b) {
        if (b != base && (sk.parent(b) < 0 || !under[static_cast<size_t>(sk.parent(b))])) continue;
        under[static_cast<size_t>(b)] = 1;
        rig.head_bones.push_back(b);
      }
      int kept = sk.parent(base);
      for (; kept >= 0 && !rig.tick_bone[kept]; kept = sk.parent(kept)) rig.head_between.push_back(kept);
      std::reverse(rig.head_between.begin(), rig.head_between.end());
      rig.head_kept_bone = kept;
    }
  }
  for (int b = 0; b < sk.bone_count(); ++b) {
    if (rig.dynamic_bone[b] || (limb_bone[b] && !leg_ik_bone[b])) rig.touched_bones.push_back(b);
  }
  if (rig.legs.empty()) {
    build_drape(roles, rig);
    build_crawl_flesh(rig, roles);
  }
}

// Girdle bone i's model matrix with the spine flexed by `flex` (AnimRig::flex_sign).
Mat2x3 flexed_girdle(const AnimRig& rig, size_t i, float flex) {
  return rig.model_rest[rig.root] * rig.flexed_girdle_rel(i, flex / static_cast<float>(rig.flex_count));
}

// The spine's flexion (AnimRig::flex_sign): two leg girdles rigid to the root, each reached
// by its own chain of spine bones.
void build_flex(AnimRig& rig) {
  if (rig.girdles.size() != 2 || rig.girdle_bones.empty()) return;
  const Skeleton& sk = rig.skeleton;
  rig.flex_sign.assign(static_cast<size_t>(sk.bone_count()), 0);
  std::vector<int> girdle_of(static_cast<size_t>(sk.bone_count()), -1);
  for (const RigLeg& leg : rig.legs) girdle_of[leg.girdle_bone] = leg.girdle;
  for (int gb : rig.girdle_bones) {
    std::vector<int> chain;
    for (int b = sk.parent(gb); b >= 0 && b != rig.root; b = sk.parent(b)) chain.push_back(b);
    const int sign = girdle_of[gb] == 0 ? -1 : girdle_of[gb] == 1 ? 1 : 0;
    for (int b : chain) {
      if (sign == 0 || (rig.flex_sign[b] != 0 && rig.flex_sign[b] != sign)) {  // a chain shared by both girdles
        rig.flex_sign.clear();
        rig.flex_chains.clear();
        rig.flex_count = 0;
        return;
      }
      if (rig.flex_sign[b] == 0) ++rig.flex_count;
      rig.flex_sign[b] = static_cast<int8_t>(sign);
    }
    rig.flex_chains.emplace_back(chain.rbegin(), chain.rend());
  }
  if (rig.flex_count == 0) {
    rig.flex_sign.clear();
    rig.flex_chains.clear();
    return;
  }
  if (rig.tail_between.empty() && rig.tail_base_bone >= 0) {  // a tail hanging from the flexing spine
    std::vector<int> between;
    for (int b = rig.skeleton.parent(rig.tail[0]); b >= 0 && b != rig.tail_base_bone; b = rig.skeleton.parent(b)) between.push_back(b);
    if (std::any_of(between.begin(), between.end(), [&](int b) { return rig.flex_sign[b] != 0; }))
      rig.tail_flex_between.assign(between.rbegin(), between.rend());
  }
  if (!rig.neck.empty() && rig.dynamic_bone[rig.neck.back()]) {
    int turned = 0;
    for (int b = sk.parent(rig.neck.back()); b >= 0; b = sk.parent(b)) turned += rig.flex_sign[b];
    if (turned != 0) rig.flex_neck = rig.neck.back(), rig.flex_neck_turn = static_cast<float>(-turned);
  }
  // How each girdle's joint moves, to second order (central differences of the chain's FK).
  constexpr float h = 0.05f;
  for (size_t g = 0; g < rig.girdles.size(); ++g) {
    RigGirdle& girdle = rig.girdles[g];
    const int gb = rig.legs[girdle.legs.front()].girdle_bone;
    const size_t i = static_cast<size_t>(std::find(rig.girdle_bones.begin(), rig.girdle_bones.end(), gb) - rig.girdle_bones.begin());
    if (i == rig.girdle_bones.size()) continue;
    const glm::vec2 local = inverse(rig.model_rest[gb]).apply(girdle.joint_ms);
    const glm::vec2 up = flexed_girdle(rig, i, h).apply(local), down = flexed_girdle(rig, i, -h).apply(local);
    girdle.flex_d1 = (up - down) / (2.0f * h);
    girdle.flex_d2 = (up + down - 2.0f * girdle.joint_ms) / (2.0f * h * h);
  }
}

}  // namespace

Mat2x3 AnimRig::flexed_girdle_rel(size_t i, float step) const {
  const float c = std::cos(step), s = std::sin(step);
  const Mat2x3 turn[2] = {frame_matrix({c, -s}, {0.0f, 0.0f}), frame_matrix({c, s}, {0.0f, 0.0f})};  // by −step, +step
  Mat2x3 m;
  for (int b : flex_chains[i]) m = m * rest_local_m[b] * turn[flex_sign[b] > 0];
  return m * rest_local_m[girdle_bones[i]];
}

RigRoles rig_roles(const Creature& creature) {
  RigRoles roles;
  roles.root = creature.root;
  roles.skull = creature.skull;
  roles.back = creature.back;
  roles.neck = creature.neck;
  roles.tail = creature.tail;
  roles.flat_contact = creature.contact == ContactMode::kFlat;
  roles.gait_family = creature.gait_family;
  roles.weight_kg = creature.weight_kg;
  roles.skull_variant = creature.skull_variant;
  for (const Limb& limb : creature.limbs) {
    roles.limbs.push_back({limb.kind, limb.girdle_bone, limb.bones, limb.side, limb.bend_sign,
                           2 * static_cast<int>(limb.girdle) + limb.slot});
  }
  // The body's outline vertices, each with the palette entry it follows most (a mid joint's
  // belongs to a limb: bone -1).
  if (Result<BodyMesh> body = try_build_body(creature)) {
    const int bones = creature.skeleton.bone_count();
    for (size_t p = 0; p < body->parts.size(); ++p) {
      for (uint32_t i : body->parts[p].outline) {
        const BodyVertex& v = body->vertices[i];
        const size_t most = static_cast<size_t>(std::max_element(v.weights.begin(), v.weights.end()) - v.weights.begin());
        const int bone = v.bones[most] < bones ? static_cast<int>(v.bones[most]) : -1;
        roles.flesh.push_back({bone, v.position_ms, static_cast<int>(p), v.bones, v.weights});
      }
    }
    roles.mid_joints = body->mid_joints;
  }
  return roles;
}

float knee_ahead(const RigLeg& leg, float height) {
  const float d = std::clamp(height + leg.foot_offset_ms.y, leg.fold, 0.999f * leg.reach);  // joint to ankle
  return solve_two_bone_ik_directions({0.0f, 0.0f}, leg.upper, leg.lower, {0.0f, -d}, leg.bend).middle.x;
}

std::shared_ptr<const AnimRig> build_anim_rig(const Creature& creature) {
  return build_anim_rig(creature.skeleton, creature.rest_pose, rig_roles(creature));
}

std::shared_ptr<const AnimRig> build_anim_rig(const Skeleton& skeleton, const Pose& rest_pose, const RigRoles& asked) {
  auto rig = std::make_shared<AnimRig>();
  rig->skeleton = skeleton;
  rig->rest_pose = rest_pose;
  const Skeleton& sk = rig->skeleton;
  rig->model_rest = ossa::model_matrices(sk, rig->rest_pose.locals);
  RigRoles roles = asked;
  if (legs_without_reach_to_arms(sk, roles)) roles.gait_family = GaitFamily::kAuto;  // chosen from the legs it has
  if (!legs_hold_back_up(sk, rig->model_rest, roles)) {
    rig->legs_as_fins = true;
    for (RigLimbRole& limb : roles.limbs) {
      if (limb.kind == LimbKind::kLeg) limb.kind = LimbKind::kFin;
    }
    roles.gait_family = GaitFamily::kLegless;
  }
  rig->root = roles.root;
  rig->skull = roles.skull;
  rig->back = roles.back;
  rig->neck = roles.neck;
  rig->tail = roles.tail;
  rig->flat_contact = roles.flat_contact;
  rig->root_rest_y = bone_start(rig->model_rest[roles.root]).y;

  for (const RigLimbRole& limb : roles.limbs) {
    if (limb.kind == LimbKind::kArm) rig->arms.push_back(rig_limb(limb));
    if (limb.kind == LimbKind::kWing) rig->wings.push_back(rig_limb(limb));
    if (limb.kind == LimbKind::kFin) rig->fins.push_back(rig_limb(limb));
  }
  build_legs(roles, *rig);

  float hip = 0.0f;
  for (const RigGirdle& g : rig->girdles) hip += g.rest_height;
  hip = rig->girdles.empty() ? std::max(rig->root_rest_y, 0.05f) : hip / static_cast<float>(rig->girdles.size());
  rig->hip_height = std::max(hip, 0.02f);
  float x_min = 0.0f, x_max = 0.0f, y_max = 0.0f;
  for (int b = 0; b < sk.bone_count(); ++b) {
    y_max = std::max({y_max, bone_start(rig->model_rest[b]).y, bone_end(rig->model_rest[b], sk.length(b)).y});
    const glm::vec2 p = bone_start(rig->model_rest[b]);
    x_min = std::min(x_min, p.x);
    x_max = std::max(x_max, p.x);
  }
  rig->body_half_length = std::max(0.5f * (x_max - x_min), 0.05f);
  rig->scale = RigScale::of(2.0f * rig->body_half_length);
  build_foot_flesh(*rig, roles);
  for (RigLimb& arm : rig->arms) arm.flesh_outline = limb_flesh(*rig, roles, arm.bones, &arm.flesh_margin, &arm.flesh_mids);
  for (int b = 0; b < sk.bone_count(); ++b) {  // the extent from the root counts bone ends too
    const float e = bone_end(rig->model_rest[b], sk.length(b)).x;
    x_min = std::min(x_min, e);
    x_max = std::max(x_max, e);
  }
  const float root_x = bone_start(rig->model_rest[roles.root]).x;
  rig->body_back = std::min(x_min - root_x, -0.025f);
  rig->body_front = std::max(x_max - root_x, 0.025f);
  rig->body_top = std::max(y_max, 0.01f);
  rig->outline_arms = distinct_outlines(*rig, rig->arms);
  rig->outline_fins = distinct_outlines(*rig, rig->fins);
  rig->outline_wings = distinct_outlines(*rig, rig->wings);
  if (rig->girdles.size() == 1) {
    const RigGirdle& g = rig->girdles[0];
    for (const RigLimbRole& limb : roles.limbs) {
      if (limb.kind != LimbKind::kArm && limb.kind != LimbKind::kWing) continue;
      const glm::vec2 v = bone_start(rig->model_rest[limb.bones[0]]) - g.joint_ms;
      if (v.x > rig->front_shoulder.x) {
        rig->front_shoulder = v;
        // Its rest height above the ground, less the clearance the body keeps under a
        // shoulder, and a little.
        rig->front_slack = v.y + g.rest_height - 0.2f * rig->hip_height;
      }
    }
  }
  build_fk_plan(roles, *rig);  // (a legless rig's root_rest_y: build_drape)
  if (rig->legs.empty()) {
    rig->crawl_climb = std::min(kCrawlClimbOfRest * rig->root_rest_y, kCrawlClimbOfLength * (rig->body_front - rig->body_back));
  }
  build_trunk(*rig);
  build_flesh(*rig, roles);
  build_flex(*rig);
  anim::build_pentapedal(*rig);
  rig->weight_kg = roles.weight_kg;
  rig->skull_variant = roles.skull_variant;
  rig->gait_family = roles.gait_family == GaitFamily::kAuto ? anim::choose_gait_family(*rig) : roles.gait_family;
  rig->traits = anim::gait_family_traits(rig->gait_family, *rig);
  rig->traits_kept = true;
  return rig;
}

}  // namespace ossa
