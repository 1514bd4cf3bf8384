#include "ossa/draw/sprite_mesh.h"

// The sprite mesh builder: anchor mapping [Z 7.4], strips, smooth weights across chain
// joints, layers (sprite_mesh.h). The sprite set is in sprite_set.cpp, the sprite choice in
// sprite_choice.cpp, the mid-joint frames and chain joints in sprite_skinning.cpp.

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "ossa/skeleton/pose.h"

#include <glm/common.hpp>

namespace ossa {

namespace {

// Drawing order inside a layer (as in export_svg): ribs behind girdles behind the spine and
// skull, limbs on top from the girdle outwards.
int kind_order(BoneKind kind) {
  switch (kind) {
    case BoneKind::kRib: return 0;
    case BoneKind::kScapula:
    case BoneKind::kPelvis: return 1;
    case BoneKind::kRoot:
    case BoneKind::kNeckVertebra:
    case BoneKind::kBackVertebra:
    case BoneKind::kTailVertebra: return 2;
    case BoneKind::kSkull: return 3;
    case BoneKind::kUpperLimb: return 4;
    case BoneKind::kLowerLimb: return 5;
    case BoneKind::kHand: return 6;
  }
  return 7;
}

// The limb index of a leg's hand (foot) bone, or -1.
int s_kind_hand(const Creature& c, int bone) {
  if (c.skeleton.kind(bone) != BoneKind::kHand) return -1;
  for (size_t i = 0; i < c.limbs.size(); ++i) {
    if (c.limbs[i].bones[2] == bone && c.limbs[i].kind == LimbKind::kLeg) return static_cast<int>(i);
  }
  return -1;
}

// Maps the sprite's unit box onto a bone's frame [Z 7.4: "two offsets per bone, to the joint
// with the parent and to the joint with the child, so the placement fits whatever the size"].
// In design space (u·r, v) — height 1, width r — the anchors lie 1/aspect apart; a similarity
// takes the parent anchor to (0, 0) and the child anchor to (length, 0), then the bone's
// perpendicular axis is stretched by k so the drawn height is drawn_height(): width / thickness
// (the sprite's thickness, SpriteInfo), or max(aspect·length, width) without one.
struct SpriteFrame {
  glm::vec2 p{0.0f};     // parent anchor, unit box
  float r = 1.0f;        // design width / height
  glm::vec2 e{1.0f, 0.0f};  // unit axis parent → child anchor, design space
  float sx = 1.0f, sy = 1.0f;  // design units → metres along / across the bone (sy signed: flip)

  glm::vec2 map(glm::vec2 uv) const {
    const glm::vec2 d((uv.x - p.x) * r, uv.y - p.y);
    return {(d.x * e.x + d.y * e.y) * sx, (e.x * d.y - e.y * d.x) * sy};
  }
};

float drawn_height(const SpriteInfo& info, float length, float width) {
  if (info.thickness > 0.0f && width > 0.0f) return width / info.thickness;
  return std::max(info.aspect * length, width);
}

SpriteFrame sprite_frame(const SpriteInfo& info, float length, float width, bool flip) {
  SpriteFrame f;
  f.p = info.parent_anchor;
  const float du = info.child_anchor.x - info.parent_anchor.x;
  const float dv = info.child_anchor.y - info.parent_anchor.y;
  const float span = 1.0f / info.aspect;  // anchor distance in design units
  f.r = std::sqrt(std::max(span * span - dv * dv, 1e-12f)) / std::max(du, 1e-6f);
  f.e = glm::vec2(du * f.r, dv) / span;
  f.sx = length / span;  // = aspect · length per design unit
  const float k = drawn_height(info, length, width) / std::max(info.aspect * length, 1e-12f);
  f.sy = f.sx * k * (flip ? -1.0f : 1.0f);
  return f;
}

}  // namespace

namespace {

// Whether the bone is a leg's hand bone whose sprite has a contact part (toes, hoof, claws).
// Such a foot gets a level frame and the contact ramp whatever its rest angle: a foot that
// stands straight down at rest (a pig's hind hoof) turns its contact part by 0, and still
// needs the level frame to keep it flat while the bone rolls over it in stance.
bool has_contact_part(const Creature& c, int bone, const SpriteInfo& info) {
  return s_kind_hand(c, bone) >= 0 && info.contact_from >= 0.0f;
}

// A sprite's drawn half height (metres) — the joint's thickness as the sprite shows it.
// How far a foot's contact part turns (radians, in the bone's frame) so it stands on the ground
// in the rest pose: the angle from the bone's direction to straight down, for the hand bone of
// a leg whose sprite has a contact part (0 otherwise, and 0 for a foot straight down).
constexpr float kContactRamp = 0.06f;
float contact_angle(const Creature& c, int bone, const SpriteInfo& info, const Mat2x3& rest) {
  if (!has_contact_part(c, bone, info)) return 0.0f;
  // World down in the bone's frame (the rest frame's inverse rotation; a mirror flips it).
  const glm::vec2 x(rest.m[0], rest.m[1]), y(rest.m[2], rest.m[3]);
  const glm::vec2 down(glm::dot(glm::vec2(0.0f, -1.0f), x) / std::max(glm::dot(x, x), 1e-12f),
                       glm::dot(glm::vec2(0.0f, -1.0f), y) / std::max(glm::dot(y, y), 1e-12f));
  return std::atan2(down.y, down.x);
}

// Whether a bone's sprite is drawn mirrored across its bone: Skeleton::sprite_flip_y, and a
// leg's flat foot (no contact part to stand up) with its sole on the ground, its art's top up
// whichever way the rest pose points the foot (a hind foot folded back points it down).
bool drawn_flipped(const Creature& c, int bone, const SpriteInfo& info, const Mat2x3& rest) {
  bool flip = c.skeleton.sprite_flip_y(bone);
  if (s_kind_hand(c, bone) >= 0 && !(info.contact_from >= 0.0f) && rest.m[3] < 0.0f) flip = !flip;
  return flip;
}

float half_height(const SpriteInfo& info, float length, float width) {
  return 0.5f * drawn_height(info, length, width);
}

// One blended chain joint: parent and child bones, the palette indices of its mid-joint
// frames (in turn order; none: blend parent and child directly), the blend's half width
// (metres along either bone) and, at a limb joint, how the parent's end tucks under the
// child's start: its drawing squeezed across the bone to `squeeze` of its height from
// `squeeze_to` metres from the joint on, ramping in from `squeeze_from` (both negative: on
// the parent).
struct JointBlend {
  int parent = -1, child = -1;
  std::array<int, kSmoothJointFrames> frame{};
  int frames = 0;
  float half_width = 0.0f;
  bool limb = false;
  float squeeze = 1.0f, squeeze_from = 0.0f, squeeze_to = 0.0f;
};

struct BoneWeight {
  int bone = 0;
  float weight = 0.0f;
};

// The weights across `j` of a point `s` metres from the joint along its bone (negative
// toward the parent): parent, the mid-joint frames in turn order, child, placed evenly over
// [-half_width, half_width], and between two neighbours a blend linear in s. So the joint's
// turn spreads evenly over the blend and the bone's axis bends along a circular arc (a
// smoothstep turns 1.5 times faster at its middle and folds the inside of a bent knee
// sooner), and a linear blend never spans more than one step of the turn.
void joint_weights(const JointBlend& j, float s, BoneWeight out[2]) {
  const int steps = j.frames + 1;
  const float x = std::clamp((s + j.half_width) / (2.0f * j.half_width), 0.0f, 1.0f) * static_cast<float>(steps);
  const int i = std::min(static_cast<int>(x), steps - 1);
  const float t = x - static_cast<float>(i);
  const auto at = [&](int k) { return k == 0 ? j.parent : k == steps ? j.child : j.frame[static_cast<size_t>(k - 1)]; };
  out[0] = {at(i), 1.0f - t};
  out[1] = {at(i + 1), t};
}

// Across-the-bone scale of the parent's end at `s` metres from the joint `j` (1 outside it).
float end_squeeze(const JointBlend& j, float s) {
  if (j.squeeze >= 1.0f || s <= j.squeeze_from) return 1.0f;
  const float ramp = std::clamp((s - j.squeeze_from) / (j.squeeze_to - j.squeeze_from), 0.0f, 1.0f);
  return 1.0f + (j.squeeze - 1.0f) * ramp;
}

// A sprite's reach (joint_reach) at one end in metres across its bone frame: x toward -y,
// y toward +y (a flipped sprite's v runs along -y).
glm::vec2 reach_ms(const SpriteInfo& info, bool child_end, float drawn_height, bool flip) {
  const glm::vec2 r = joint_reach(info, child_end) * drawn_height;
  return flip ? glm::vec2(r.y, r.x) : r;
}

}  // namespace

Result<SpriteMesh> try_build_sprite_mesh(const Creature& creature, const SpriteSet& sprites,
                                         const SpriteMeshOptions& options) {
  const int n = creature.skeleton.bone_count();
  if (n > kMaxSpriteMeshBones) {
    return Error::at(creature.name, "skeleton", "expected at most " + std::to_string(kMaxSpriteMeshBones) +
                                                    " bones for a sprite mesh, got " + std::to_string(n));
  }
  return build_sprite_mesh(creature, sprites, options);
}

SpriteMesh build_sprite_mesh(const Creature& creature, const SpriteSet& sprites,
                             const SpriteMeshOptions& options) {
  const Skeleton& s = creature.skeleton;
  const int n = s.bone_count();
  OSSA_ASSERT(n <= kMaxSpriteMeshBones, "build_sprite_mesh: more bones than uint8 bone indices hold");
  const std::vector<BoneLocal>& locals =
      creature.rest_pose.locals.size() == static_cast<size_t>(n) ? creature.rest_pose.locals : s.rest_locals();
  const std::vector<Mat2x3> rest = model_matrices(s, locals);

  SpriteMesh mesh;
  mesh.bone_sprites.reserve(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) mesh.bone_sprites.push_back(sprite_for_bone(creature, i));

  // Smooth skinning: each chain joint's blend, stored on the parent (its end) and the child
  // (its start) alike. The bind pose straightens every blended joint, so the two sprites
  // overlap along one line there and the same weight at the same distance from the joint is
  // the same point on both: they bend as one. (Blending in a bent bind pose tears a sprite's
  // end, which lies off its neighbour's axis, when the joint turns the other way.)
  const bool smooth = options.smooth_weights && creature.smooth_skinning;
  std::vector<JointBlend> start_blend(static_cast<size_t>(n)), end_blend(static_cast<size_t>(n));
  std::vector<BoneLocal> bind_locals = locals;
  const auto limb_joint = [&](int child) {
    const BoneKind k = s.kind(child);
    return k == BoneKind::kLowerLimb || k == BoneKind::kHand;
  };
  if (smooth) {
    std::vector<int> chain = chain_children(s, locals);
    // A foot drawn flat has its sole on the ground from the ankle on: blending the ankle would
    // swing the sole's start with the shin, below the ground; its sprite stays rigid there.
    for (int p = 0; p < n; ++p) {
      const int c = chain[static_cast<size_t>(p)];
      if (c >= 0 && s_kind_hand(creature, c) >= 0 && mesh.bone_sprites[static_cast<size_t>(c)] == SpriteId::kFlatFoot) {
        chain[static_cast<size_t>(p)] = -1;
      }
    }
    // kSmoothJointFrames frames per limb joint while the uint8 indices last, else one (which
    // every genome within its limits has room for, see kMaxSpriteMeshBones).
    int limb_joints = 0;
    for (const int c : chain) limb_joints += c >= 0 && limb_joint(c);
    int frames_per_joint = kSmoothJointFrames;
    while (frames_per_joint > 0 && n + frames_per_joint * limb_joints > kMaxSpriteMeshBones + 1) frames_per_joint -= 2;
    int mids = 0;
    for (int p = 0; p < n; ++p) {
      const int c = chain[static_cast<size_t>(p)];
      if (c < 0) continue;
      const SpriteInfo& pi = sprites[mesh.bone_sprites[static_cast<size_t>(p)]];
      const SpriteInfo& ci = sprites[mesh.bone_sprites[static_cast<size_t>(c)]];
      const float hp = half_height(pi, s.length(p), std::max(s.width(p), 0.0f));
      const float hc = half_height(ci, s.length(c), std::max(s.width(c), 0.0f));
      const float half_width =
          std::min({kSmoothBlend * 0.5f * (hp + hc), kSmoothMaxSpan * s.length(p), kSmoothMaxSpan * s.length(c)});
      if (!(half_width > 0.0f) || !std::isfinite(half_width)) continue;
      JointBlend j;
      j.parent = p, j.child = c, j.half_width = half_width, j.limb = limb_joint(c);
      if (j.limb) {
        j.frames = std::max(frames_per_joint, 0);
        for (int f = 0; f < j.frames; ++f) j.frame[static_cast<size_t>(f)] = n + mids++;
        // Straightened, the parent's end and the child's start lie on each other; the child
        // draws on top, and wherever the parent's end reaches further across the bone (a
        // thicker parent, or a bigger knob at that end of the art) its outline shows beside
        // the child's as a second one. So the parent's end shrinks across the bone to within
        // the child's reach, from where the child's sprite begins to half way to the joint.
        const glm::vec2 pr = reach_ms(pi, true, 2.0f * hp, drawn_flipped(creature, p, pi, rest[static_cast<size_t>(p)]));
        const glm::vec2 cr = reach_ms(ci, false, 2.0f * hc, drawn_flipped(creature, c, ci, rest[static_cast<size_t>(c)]));
        j.squeeze = std::min(1.0f, std::min(pr.x > 0.0f ? cr.x / pr.x : 1.0f, pr.y > 0.0f ? cr.y / pr.y : 1.0f));
        const float child_begins = -ci.parent_anchor.x / (ci.child_anchor.x - ci.parent_anchor.x) * s.length(c);
        j.squeeze_from = std::max(child_begins, -0.5f * s.length(p));
        j.squeeze_to = 0.5f * j.squeeze_from;
        if (!(j.squeeze > 0.0f) || !(j.squeeze_from < 0.0f)) j.squeeze = 1.0f;
      }
      end_blend[static_cast<size_t>(p)] = j;
      start_blend[static_cast<size_t>(c)] = j;
      bind_locals[static_cast<size_t>(c)].angle_ls = 0.0f;
    }
  }
  const std::vector<Mat2x3> model = smooth ? model_matrices(s, bind_locals) : rest;
  mesh.inverse_bind.reserve(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) mesh.inverse_bind.push_back(inverse(model[static_cast<size_t>(i)]));
  for (const JointBlend& j : end_blend) {
    for (int f = 0; f < j.frames; ++f) {
      MidJoint mid;
      mid.parent = j.parent, mid.child = j.child;
      mid.turn = static_cast<float>(f + 1) / static_cast<float>(j.frames + 1);
      const Mat2x3 bind =
          mid_joint_frame(model[static_cast<size_t>(j.parent)], model[static_cast<size_t>(j.child)], mid.turn);
      mid.rest_half = mid_joint_half_turn(model[static_cast<size_t>(j.parent)], model[static_cast<size_t>(j.child)]);
      mid.inverse_bind = inverse(bind);
      mesh.mid_joints.push_back(mid);
    }
  }
  // Feet whose contact part stands on the ground get a level frame (MidJoint::level): their
  // toes, hooves and claws keep their rest turn while the foot bone turns over them, as planted
  // toes do — where the uint8 palette indices have room (else the contact part stays rigid).
  std::vector<int> level_entry(static_cast<size_t>(n), -1);
  for (int b = 0; b < n && smooth; ++b) {
    const SpriteInfo& info = sprites[mesh.bone_sprites[static_cast<size_t>(b)]];
    if (!has_contact_part(creature, b, info)) continue;
    if (n + static_cast<int>(mesh.mid_joints.size()) >= kMaxSpriteMeshBones + 1) break;
    MidJoint j;
    j.level = true;
    j.parent = j.child = b;
    j.point_ls = {s.length(b), 0.0f};
    const glm::vec2 x(rest[static_cast<size_t>(b)].m[0], rest[static_cast<size_t>(b)].m[1]);
    j.rest_x = glm::length(x) > 0.0f ? glm::normalize(x) : glm::vec2(1.0f, 0.0f);
    Mat2x3 bind = model[static_cast<size_t>(b)];
    const glm::vec2 tip = bind.apply(j.point_ls);
    bind.m[4] = tip.x;
    bind.m[5] = tip.y;
    j.inverse_bind = inverse(bind);
    level_entry[static_cast<size_t>(b)] = n + static_cast<int>(mesh.mid_joints.size());
    mesh.mid_joints.push_back(j);
  }

  std::vector<int> order;
  for (int i = 0; i < n; ++i) {
    if (s.length(i) > 1e-6f && std::isfinite(s.length(i))) order.push_back(i);
  }
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    const int la = static_cast<int>(s.layer(a)), lb = static_cast<int>(s.layer(b));
    if (la != lb) return la < lb;
    return kind_order(s.kind(a)) < kind_order(s.kind(b));
  });

  mesh.vertices.reserve(order.size() * (smooth ? 64 : 8));
  mesh.indices.reserve(order.size() * (smooth ? 240 : 18));
  std::vector<float> columns;
  int layer = 0;
  for (int bone : order) {
    const int bone_layer = static_cast<int>(s.layer(bone));
    while (layer < bone_layer) mesh.layer_begin[static_cast<size_t>(++layer)] = static_cast<uint32_t>(mesh.indices.size());

    const SpriteInfo& info = sprites[mesh.bone_sprites[static_cast<size_t>(bone)]];
    const SpriteFrame frame = sprite_frame(info, s.length(bone), std::max(s.width(bone), 0.0f),
                                           drawn_flipped(creature, bone, info, rest[static_cast<size_t>(bone)]));
    const Mat2x3& m = model[static_cast<size_t>(bone)];
    const float shade = s.layer(bone) == Layer::kFar ? options.far_shade : 1.0f;
    const float pu = info.parent_anchor.x, cu = info.child_anchor.x;
    const float metres_per_u = s.length(bone) / (cu - pu);  // along the bone
    const JointBlend& at_start = start_blend[static_cast<size_t>(bone)];
    const JointBlend& at_end = end_blend[static_cast<size_t>(bone)];
    // A skull's muzzle takes the creature's share of its length (SpriteInfo::snout_from).
    const bool snout = s.kind(bone) == BoneKind::kSkull && info.snout_from > pu && info.snout_from < cu;
    const float snout_x0 = snout ? frame.map({info.snout_from, info.parent_anchor.y}).x : 0.0f;
    const float snout_x = (1.0f - std::clamp(creature.skull_snout, 0.05f, 0.95f)) * s.length(bone);
    const auto warp = [&](float x) {
      if (!snout || !(snout_x0 > 0.0f) || !(snout_x0 < s.length(bone))) return x;
      return x < snout_x0 ? x * snout_x / snout_x0
                          : snout_x + (x - snout_x0) * (s.length(bone) - snout_x) / (s.length(bone) - snout_x0);
    };
    // A foot's contact part stands on the ground in the rest pose: turned about the contact
    // point (the child anchor, the bone's end) from the bone's direction to straight down,
    // ramping in over kContactRamp of u before contact_from (SpriteInfo::contact_from).
    const float contact_turn = contact_angle(creature, bone, info, rest[static_cast<size_t>(bone)]);
    const bool contact = has_contact_part(creature, bone, info);
    const float ramp_from = info.contact_from - kContactRamp;
    const auto turn = [&](glm::vec2 p, float u) {
      if (!contact || u <= ramp_from) return p;
      const float t = std::clamp((u - ramp_from) / kContactRamp, 0.0f, 1.0f);
      const float a = contact_turn * t * t * (3.0f - 2.0f * t);
      const glm::vec2 pivot(s.length(bone), 0.0f), d = p - pivot;
      return pivot + glm::vec2(std::cos(a) * d.x - std::sin(a) * d.y, std::sin(a) * d.x + std::cos(a) * d.y);
    };

    // Columns: the sprite's ends and both anchors; around each blended joint kSmoothColumns
    // more on either side, evenly over the blend, and where the end's squeeze ramps (those on
    // the sprite).
    columns.assign({0.0f, pu, cu, 1.0f});
    for (const auto& [j, joint_u] : {std::pair{&at_start, pu}, std::pair{&at_end, cu}}) {
      if (j->parent < 0) continue;
      // Limb joints turn far (finer columns); spine joints a few degrees each.
      const int per_side = j->limb ? kSmoothColumns : kSmoothSpineColumns;
      for (int k = -per_side; k <= per_side; ++k) {
        const float u = joint_u + j->half_width / metres_per_u * static_cast<float>(k) / per_side;
        if (u > 0.0f && u < 1.0f) columns.push_back(u);
      }
    }
    if (at_end.squeeze < 1.0f) {
      for (const float at : {at_end.squeeze_from, at_end.squeeze_to}) {
        if (const float u = cu + at / metres_per_u; u > 0.0f && u < 1.0f) columns.push_back(u);
      }
    }
    if (snout) columns.push_back(info.snout_from);
    if (contact) {
      for (int k = 0; k <= 4; ++k) columns.push_back(ramp_from + kContactRamp * static_cast<float>(k) / 4.0f);
    }
    std::sort(columns.begin(), columns.end());
    columns.erase(std::unique(columns.begin(), columns.end(), [](float a, float b) { return b - a < 1e-5f; }),
                  columns.end());

    // Rows: one quad across the sprite, or kSmoothRows next to a limb joint (see
    // SpriteMeshOptions: a tall quad between two columns turned apart kinks its texture).
    const int rows = at_start.limb || at_end.limb ? kSmoothRows : 1;
    const auto first = static_cast<uint32_t>(mesh.vertices.size());
    for (const float u : columns) {
      // Within a joint's blend the joint's weights (the bone itself among them, perhaps at 0
      // deep in its neighbour's blend), else the bone alone. A bone's two blends never meet.
      BoneWeight w[2] = {{bone, 1.0f}, {bone, 0.0f}};
      const float s_start = (u - pu) * metres_per_u, s_end = (u - cu) * metres_per_u;
      if (at_start.parent >= 0 && s_start < at_start.half_width) {
        joint_weights(at_start, s_start, w);
      } else if (at_end.parent >= 0 && s_end > -at_end.half_width) {
        joint_weights(at_end, s_end, w);
      }
      std::array<uint8_t, 4> bones{static_cast<uint8_t>(bone), 0, 0, 0};
      std::array<float, 4> weights{0.0f, 0.0f, 0.0f, 0.0f};
      int used = 1;
      for (const BoneWeight& bw : w) {
        if (bw.bone == bone) {
          weights[0] += bw.weight;
        } else if (bw.weight > 0.0f) {
          bones[static_cast<size_t>(used)] = static_cast<uint8_t>(bw.bone);
          weights[static_cast<size_t>(used++)] = bw.weight;
        }
      }
      // The contact part follows the foot's level frame, ramping in with its turn.
      if (contact && level_entry[static_cast<size_t>(bone)] >= 0 && u > ramp_from && used < 4) {
        const float t = std::clamp((u - ramp_from) / kContactRamp, 0.0f, 1.0f);
        const float level = t * t * (3.0f - 2.0f * t);
        for (float& wk : weights) wk *= 1.0f - level;
        bones[static_cast<size_t>(used)] = static_cast<uint8_t>(level_entry[static_cast<size_t>(bone)]);
        weights[static_cast<size_t>(used++)] = level;
      }
      const float squeeze = at_end.parent >= 0 ? end_squeeze(at_end, s_end) : 1.0f;
      for (int r = 0; r <= rows; ++r) {
        const float v = static_cast<float>(r) / static_cast<float>(rows);
        glm::vec2 p = frame.map({u, v});  // bone frame: x along the bone, y across it
        p.y *= squeeze;
        p.x = warp(p.x);
        p = turn(p, u);
        SpriteVertex vert;
        vert.position_ms = m.apply(p);
        vert.uv = info.uv_min + glm::vec2(u, v) * (info.uv_max - info.uv_min);
        vert.bones = bones;
        vert.weights = weights;
        vert.shade = shade;
        mesh.vertices.push_back(vert);
      }
    }
    const auto per_column = static_cast<uint32_t>(rows + 1);
    for (uint32_t c = 0; c + 1 < columns.size(); ++c) {
      for (uint32_t r = 0; r < static_cast<uint32_t>(rows); ++r) {
        const uint32_t a = first + c * per_column + r, b = a + per_column;  // (u_c, v_r), column c+1
        mesh.indices.insert(mesh.indices.end(), {a, b, b + 1, a, b + 1, a + 1});
      }
    }
  }
  while (layer < kLayerCount) mesh.layer_begin[static_cast<size_t>(++layer)] = static_cast<uint32_t>(mesh.indices.size());
  mesh.layer_begin[0] = 0;

  // The rest pose as drawn: the bind pose skinned to it (the same where nothing is blended).
  mesh.rest_positions.reserve(mesh.vertices.size());
  if (!smooth) {
    for (const SpriteVertex& v : mesh.vertices) mesh.rest_positions.push_back(v.position_ms);
  } else {
    std::vector<Mat2x3> palette(static_cast<size_t>(mesh.palette_size()));
    for (int i = 0; i < n; ++i) palette[static_cast<size_t>(i)] = rest[static_cast<size_t>(i)] * mesh.inverse_bind[static_cast<size_t>(i)];
    mid_joint_palette(mesh.mid_joints, rest, palette);
    for (const SpriteVertex& v : mesh.vertices) mesh.rest_positions.push_back(skin_vertex(v, palette));
  }
  return mesh;
}

Box sprite_mesh_bounds(const SpriteMesh& mesh) {
  if (mesh.vertices.empty()) return Box{};
  const bool rest = mesh.rest_positions.size() == mesh.vertices.size();
  const auto at = [&](size_t i) { return rest ? mesh.rest_positions[i] : mesh.vertices[i].position_ms; };
  Box b{at(0), at(0)};
  for (size_t i = 1; i < mesh.vertices.size(); ++i) {
    b.min_ws = glm::min(b.min_ws, at(i));
    b.max_ws = glm::max(b.max_ws, at(i));
  }
  return b;
}

}  // namespace ossa
