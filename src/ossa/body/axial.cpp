// The axial body: one tube from the snout tip to the tail tip over the skull and the spine —
// head (by skull variant and the genome's skull shape), neck, trunk and tail (body_parts.h).
//
// Profiles, in metres along the dorsal normal (top) and against it (bottom), as fixed +
// soft (the girth factor scales the soft part):
//   head   the skull's height shapes it: a mammal's muzzle, domed cranium and jaw; a bird's
//          pointed beak and round cranium; a reptile's long flat head; a fish's pointed one
//   neck   from the throat behind the jaw to the chest: thin over the vertebrae on top
//   trunk  back line thin over the spine (spinous processes, a withers bump in mammals, a
//          hump when the genome has one); belly line below the ribs (their tips, measured on
//          the skeleton) and rising over the flank to the pelvis
//   tail   from the croup and the buttock, tapering with the tail vertebrae to the tip
// Every side is capped so that the rest pose stays above the ground by a clearance (a body
// must not touch the ground when the legs crouch for a jump, 0.2 hip heights).

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "ossa/body/body_parts.h"

namespace ossa::body {

namespace {

// At most this many cross-sections along the head-to-tail chain (the examples use 40 to 90).
constexpr int kMaxSectionsOfChain = 400;

struct Profile {
  float top_fixed, top_soft, bottom_fixed, bottom_soft;
};

Profile mix(const Profile& a, const Profile& b, float t) {
  return {a.top_fixed + (b.top_fixed - a.top_fixed) * t, a.top_soft + (b.top_soft - a.top_soft) * t,
          a.bottom_fixed + (b.bottom_fixed - a.bottom_fixed) * t, a.bottom_soft + (b.bottom_soft - a.bottom_soft) * t};
}

// The head at u (0 snout tip … 1 the back of the skull), in units of the skull height H.
Profile head_profile(int variant, float snout, float u) {
  const float f = std::clamp(snout, 0.05f, 0.95f);
  const float c = std::clamp((u - f) / std::max(1.0f - f, 1e-3f), 0.0f, 1.0f);  // 0 eye … 1 occiput
  const float m = std::clamp(u / f, 0.0f, 1.0f);                                  // 0 tip … 1 eye
  switch (variant) {
    case 1: {  // bird: beak to a point, round cranium
      const float top = u < f ? 0.03f + 0.22f * std::pow(m, 1.2f) : 0.25f + 0.22f * std::sin(3.1416f * std::min(c * 0.8f, 1.0f));
      const float bottom = u < f ? 0.02f + 0.16f * std::pow(m, 1.3f) : 0.18f + 0.16f * std::sin(3.1416f * std::min(c * 0.7f, 1.0f));
      return {top, 0.03f, bottom, 0.03f};
    }
    case 2: {  // reptile: long, flat, a broad jaw
      const float top = 0.14f + 0.12f * m + 0.1f * c;
      const float bottom = 0.16f + 0.1f * m + 0.1f * c;
      return {top, 0.04f, bottom, 0.05f};
    }
    case 3: {  // fish: pointed snout opening into the body
      const float top = 0.1f + 0.25f * m + 0.15f * c;
      const float bottom = 0.1f + 0.2f * m + 0.15f * c;
      return {top, 0.05f, bottom, 0.05f};
    }
    default: {  // mammal: muzzle, brow, domed cranium, the jaw's angle
      const float top = u < f ? 0.16f + 0.14f * std::pow(m, 1.5f) : 0.3f + 0.2f * std::sin(3.1416f * std::min(0.2f + 0.8f * c, 1.0f) * 0.75f);
      const float bottom = u < f ? 0.2f + 0.14f * m : 0.34f + 0.08f * std::sin(3.1416f * c);
      return {top, 0.04f, bottom, 0.06f};
    }
  }
}

}  // namespace

void plan_axial(const BodyRig& rig, BodyParts& plan) {
  const Creature& c = *rig.creature;
  const Chain& ch = rig.axial;
  if (ch.bones.empty() || !(ch.length() > 0.0f)) return;
  const Skeleton& sk = c.skeleton;
  const float B = rig.back_length;
  const float L = ch.length();

  // Legged bodies: the girdles' heights above the ground (for the belly's clearance).
  float girdle_height = 0.0f;
  bool legs = false;
  for (const Limb& l : c.limbs) {
    if (l.kind != LimbKind::kLeg) continue;
    legs = true;
    girdle_height = std::max(girdle_height, rig.bone_start(l.bones[0]).y);
  }
  const float clearance = legs ? 0.25f * girdle_height + 0.004f * B : 0.002f * B;

  // Chest depth: the near ribs' tips below the spine, by arc length along the chain.
  std::vector<std::pair<float, float>> ribs;  // (s, depth)
  for (int b = 0; b < sk.bone_count(); ++b) {
    if (sk.kind(b) != BoneKind::kRib || sk.layer(b) != Layer::kNear) continue;
    const glm::vec2 base = rig.bone_start(b), tip = rig.bone_end(b);
    const float best_s = ch.nearest_s(base);  // the nearest chain point to the rib's base
    const float depth = glm::dot(ch.point_at(best_s) - tip, dorsal_of(ch.tangent_at(best_s)));
    if (depth > 0.0f) ribs.emplace_back(best_s, std::max(depth, 0.7f * sk.length(b)));
  }
  std::sort(ribs.begin(), ribs.end());
  const float max_rib = ribs.empty() ? 0.0f : std::max_element(ribs.begin(), ribs.end(), [](auto a, auto b) {
                                                return a.second < b.second;
                                              })->second;
  // Without ribs: a chest half as deep as the shoulder stands (legged), or a round body.
  const float shoulder_height = ch.point_at(rig.shoulder_s).y;
  // A chest at least 0.3 back lengths deep in a legged body (a horse's is 0.65, a dog's 0.6,
  // a kangaroo's 0.5): ribs that lie along an upright spine project little depth.
  // Legless bodies: swimmers (with fins) are deep-bodied, a snake's body is a slim tube; their
  // generated ribs (one generic length) say nothing about it.
  const bool swimmer = !legs && c.count(LimbKind::kFin) > 0;
  // A legged body whose girdles stand low (crocodiles, lizards, salamanders, tortoises) is
  // low-slung: a shallower chest, and wider than deep (below).
  const bool low_slung = legs && girdle_height < 0.4f * B;
  const float min_chest = legs ? (low_slung ? 0.18f : 0.3f) * B : swimmer ? 0.3f * B : 0.05f * B;
  float chest = std::max(max_rib > 0.0f ? max_rib : (legs ? std::clamp(0.45f * shoulder_height, 0.12f * B, 0.4f * B) : 0.08f * B), min_chest);
  if (!legs) {
    chest = min_chest;
    ribs.clear();
  }
  const float last_rib_s = ribs.empty() ? rig.shoulder_s + 0.5f * (rig.hip_s - rig.shoulder_s) : ribs.back().first;
  if (max_rib > 0.0f && max_rib < min_chest) {
    for (auto& r : ribs) r.second *= min_chest / max_rib;
  }
  const auto rib_depth = [&](float s) {
    if (ribs.empty()) return chest;
    if (s <= ribs.front().first) return ribs.front().second;
    for (size_t i = 1; i < ribs.size(); ++i) {
      if (s <= ribs[i].first) {
        const float t = (s - ribs[i - 1].first) / std::max(ribs[i].first - ribs[i - 1].first, 1e-6f);
        return ribs[i - 1].second + t * (ribs[i].second - ribs[i - 1].second);
      }
    }
    return ribs.back().second;
  };
  // The pelvis reaches down to the hip joint: the flank's depth there.
  float hip_depth = 0.3f * chest;
  if (c.hip >= 0) {
    hip_depth = std::max(hip_depth, glm::dot(ch.point_at(rig.hip_s) - rig.bone_end(c.hip), dorsal_of(ch.tangent_at(rig.hip_s))));
  }
  float hump = 0.0f;
  for (const Appendage& a : c.appendages) {
    if (a.kind == AppendageKind::kHump) hump = a.size;
  }
  const bool mammal = c.skull_variant == 0 && legs;
  const float H = rig.skull_height > 0.0f ? rig.skull_height : 0.12f * B;

  // Profile by region.
  const float neck_len = rig.shoulder_s - rig.snout_s, back_len = rig.hip_s - rig.shoulder_s;
  const float tail_len = rig.tail_s - rig.hip_s;
  // Fixed: what bone sets (the spinous processes, the skull, the tail's tip); soft: muscle, fat
  // and the chest's depth, which the girth scales (the generated ribs are one generic shape).
  // A body on the ground (no legs) has its spine near its back: skin over low spines.
  const float spine_top = (legs ? 0.03f : 0.006f) * B;
  const float top_muscle = (legs ? 0.03f : 0.006f) * B;
  const Profile trunk_front{spine_top, top_muscle, 0.1f * chest, 0.75f * chest + 0.03f * B};
  const Profile tail_root{spine_top, top_muscle, 0.02f * B, std::max(0.55f * hip_depth, 0.04f * B) + 0.25f * hip_depth};
  const Profile head_back = [&] {
    Profile h = head_profile(c.skull_variant, rig.snout, 1.0f);
    return Profile{h.top_fixed * H, h.top_soft * H, h.bottom_fixed * H, h.bottom_soft * H};
  }();
  const auto profile = [&](float s) -> Profile {
    if (s < rig.snout_s && rig.snout_s > 0.0f) {  // head
      const Profile h = head_profile(c.skull_variant, rig.snout, s / rig.snout_s);
      return {h.top_fixed * H, h.top_soft * H, h.bottom_fixed * H, h.bottom_soft * H};
    }
    if (s < rig.shoulder_s && neck_len > 0.0f) {  // neck: throat → chest
      const float u = (s - rig.snout_s) / neck_len;
      const Profile throat{0.1f * head_back.top_fixed, 0.75f * head_back.top_fixed + 0.5f * head_back.top_soft,
                           0.08f * head_back.bottom_fixed, 0.72f * head_back.bottom_fixed + 0.5f * head_back.bottom_soft};
      return mix(throat, trunk_front, std::pow(smooth01(0.0f, 1.0f, u), 1.4f));
    }
    if (s <= rig.hip_s && back_len > 0.0f) {  // trunk
      const float u = (s - rig.shoulder_s) / back_len;
      float top = spine_top, top_soft = (legs ? 0.03f : 0.006f) * B + 0.01f * B * std::sin(3.1416f * u);
      if (mammal) top_soft += 0.025f * B * std::exp(-std::pow((u - 0.12f) / 0.1f, 2.0f));  // withers
      top += hump * 0.2f * B * std::exp(-std::pow((u - 0.45f) / 0.16f, 2.0f));
      // Ribcage, then the abdomen (nearly as deep), rising over the flank to the pelvis.
      const float flank_from = std::max(last_rib_s, rig.shoulder_s + 0.55f * back_len);
      float depth = s <= last_rib_s ? rib_depth(s) : 0.92f * rib_depth(last_rib_s);
      const float rise = smooth01(flank_from, rig.hip_s, s);
      depth = depth + (std::max(hip_depth, 0.35f * depth) - depth) * rise;
      // Without a neck to grow into (fish, whales, many reptiles) the trunk rises from the
      // head's height over a longer stretch, as a fish's body swells behind its gills.
      const float short_neck = 1.0f - smooth01(0.0f, 0.15f * B, neck_len);
      const float front = smooth01(rig.shoulder_s, rig.shoulder_s + (0.15f + 0.3f * short_neck) * back_len, s);
      const Profile here{top, top_soft, depth * 0.12f, 0.88f * depth + 0.035f * B * (1.0f - 0.6f * rise)};
      return mix(mix(trunk_front, head_back, short_neck), here, front);
    }
    // Tail: tapering with the vertebrae; the last sections round off to the tip.
    const float u = tail_len > 0.0f ? std::clamp((s - rig.hip_s) / tail_len, 0.0f, 1.0f) : 1.0f;
    const float taper = std::pow(1.0f - u, 0.9f);
    const int k = ch.segment_at(s);
    const float vert = k >= 0 ? 0.5f * sk.width(ch.bones[static_cast<size_t>(k)]) : 0.01f * B;
    const Profile tip{0.8f * vert, 0.2f * vert, 0.8f * vert, 0.2f * vert};
    return mix(tip, tail_root, taper * taper * (3.0f - 2.0f * taper));
  };

  // A body lying on the ground (no legs: snakes, fish, whales) keeps its belly on the ground
  // line: its depth goes above the spine instead, where its back is.
  // (Section::cut_to_top: all of what the ground cuts off its belly goes onto its back.)
  const auto legless_profile = [&](float s) { return profile(s); };

  // Section positions: dense at the snout, about B/20 apart elsewhere, and never more than
  // kMaxSectionsOfChain along the whole chain (a genome with a back far shorter than its neck
  // or tail asked for millions).
  std::vector<float> at;
  const int head_n = rig.snout_s > 0.0f ? 12 : 0;
  for (int i = 0; i < head_n; ++i) at.push_back(rig.snout_s * std::pow(static_cast<float>(i) / head_n, 1.3f));
  const float min_step = L / static_cast<float>(kMaxSectionsOfChain);
  const auto fill = [&](float from, float to, float step) {
    step = std::max(step, min_step);
    const int n = std::max(1, static_cast<int>(std::ceil((to - from) / step)));
    for (int i = 0; i < n; ++i) at.push_back(from + (to - from) * static_cast<float>(i) / n);
  };
  fill(rig.snout_s, rig.shoulder_s, B / 16.0f);
  fill(rig.shoulder_s, rig.hip_s, B / 22.0f);
  fill(rig.hip_s, L, B / 16.0f);
  at.push_back(L);
  at.erase(std::unique(at.begin(), at.end(), [](float a, float b) { return std::fabs(a - b) < 1e-6f; }), at.end());

  // The centre line smoothed over ±6 % of the back (the skull's and the neck's corners become
  // arcs the sides can follow), its tangent and dorsal normal.
  const float window = 0.06f * B;
  std::vector<glm::vec2> centre(at.size());
  for (size_t i = 0; i < at.size(); ++i) {
    const float w = std::min({window, at[i], L - at[i]});
    glm::vec2 sum(0.0f);
    float wsum = 0.0f;
    for (int k = -3; k <= 3; ++k) {
      const float wk = 4.0f - static_cast<float>(std::abs(k));
      sum += wk * ch.point_at(at[i] + w * static_cast<float>(k) / 3.0f);
      wsum += wk;
    }
    centre[i] = sum / wsum;
  }

  TubePlan tube;
  tube.kind = BodyPartKind::kAxial;
  tube.layer = Layer::kBody;
  tube.depth = c.skull_variant == 3 ? 0.55f : 0.8f;  // fish are flattened from side to side
  tube.start_cap = c.skull_variant == 1 ? Cap::kPoint : Cap::kRound;
  tube.end_cap = Cap::kPoint;
  tube.end_cap_length = c.skull_variant == 0 ? 0.6f : 0.5f;
  for (size_t i = 0; i < at.size(); ++i) {
    Section sec;
    sec.centre = centre[i];
    const glm::vec2 t = glm::normalize(centre[std::min(i + 1, at.size() - 1)] - centre[i > 0 ? i - 1 : 0] + 1e-9f * ch.tangent_at(at[i]));
    sec.dorsal = dorsal_of(t);
    const Profile p = legless_profile(at[i]);
    sec.top_fixed = std::max(p.top_fixed, 0.0f);
    sec.top_soft = std::max(p.top_soft, 0.0f);
    sec.bottom_fixed = std::max(p.bottom_fixed, 0.0f);
    sec.bottom_soft = std::max(p.bottom_soft, 0.0f);
    sec.skin = chain_skin(ch, rig.axial_joints, at[i]);
    sec.cut_to_top = legs ? 0.5f : 1.0f;
    // Above the ground by the clearance at rest, whichever side faces down.
    const float room = std::max(sec.centre.y - clearance, 0.0f);
    if (sec.dorsal.y > 0.05f) sec.bottom_cap = room / sec.dorsal.y;
    if (sec.dorsal.y < -0.05f) sec.top_cap = room / -sec.dorsal.y;
    tube.sections.push_back(sec);
  }
  // The girdles' joints (shoulders, hips) lie inside the trunk whatever the girth: a limb
  // grows out of the body, not below it (a long scapula or pelvis, a lean body).
  for (const Limb& l : c.limbs) {
    if (l.kind == LimbKind::kFin || l.bones[0] < 0) continue;
    const glm::vec2 joint = rig.bone_start(l.bones[0]);
    const float gs = ch.nearest_s(joint);  // the nearest chain point
    for (size_t i = 0; i < at.size(); ++i) {
      Section& sec = tube.sections[i];
      const float below = glm::dot(sec.centre - joint, sec.dorsal) + 0.03f * B;
      const float w = 1.0f - smooth01(0.06f * B, 0.22f * B, std::fabs(at[i] - gs));
      if (w > 0.0f && below > 0.0f) sec.bottom_fixed = std::max(sec.bottom_fixed, w * below);
    }
  }
  // A bird's beak in horn colour.
  if (c.skull_variant == 1 && rig.snout_s > 0.0f) {
    const float beak_s = rig.snout * rig.snout_s;
    for (size_t i = 0; i < at.size(); ++i) {
      if (at[i] <= beak_s) tube.sections[i].colour = glm::vec4(0.78f, 0.62f, 0.28f, 1.0f);
    }
  }
  // A legged body whose belly the ground's clearance caps is low-slung (crocodiles,
  // salamanders, tortoises, frogs): wider than deep, its cross-sections 1.3 times as wide as
  // high (body_mass.h), 1.5 when its girdles stand lower than 0.4 back lengths; a fish is
  // flattened from side to side (0.55); whales (0.9) and snakes (1) are round; birds 0.53
  // (below); others 0.8.
  float wanted = 0.0f, kept = 0.0f;
  for (const Section& sec : tube.sections) {
    wanted += sec.bottom_fixed + sec.bottom_soft;
    kept += sec.bottom(1.0f);
  }
  if (legs && wanted > 0.0f && kept < 0.7f * wanted) tube.depth = 1.3f;
  if (low_slung) tube.depth = 1.5f;
  // A bird's feathered outline is deeper than its body is wide, and a bird is lighter than
  // water (air sacs, hollow bones): 0.75 wide × 0.7 dense.
  if (c.skull_variant == 1 && c.count(LimbKind::kWing) > 0) tube.depth = 0.53f;
  if (!legs && c.skull_variant != 3) tube.depth = swimmer ? 0.9f : 1.0f;  // whales, snakes: round
  plan.tubes.push_back(std::move(tube));
}

}  // namespace ossa::body
