#include "ossa/render/sprite_mesh.h"

// Sections:
//   [SECTION] Sprite set — names, built-in anchors, sprites.json loader
//   [SECTION] Sprite choice — BoneKind + limb + contact + skull variant → SpriteId
//   [SECTION] Mesh — anchor mapping [Z 7.4], strips, weights, layers

#include <algorithm>
#include <cmath>

#include "ossa/io/json.h"
#include "ossa/math/angle.h"
#include "ossa/skeleton/pose.h"

#include <glm/common.hpp>

namespace ossa {
namespace {

constexpr size_t kSpriteCount = static_cast<size_t>(SpriteId::kCount);

constexpr const char* kSpriteNames[kSpriteCount] = {
    "skull_mammal", "skull_bird", "skull_reptile", "skull_fish", "vertebra", "tail_vertebra",
    "rib",          "scapula",    "pelvis",        "long_bone",  "paw",      "hoof",
    "flat_foot",    "bird_foot",  "wing_hand",     "fin"};

// [SECTION] Sprite set -----------------------------------------------------------------------

struct DefaultAnchors {
  float pu, pv, cu, cv, aspect;
};
// Measured from the SVG sources by tools/make-bone-sprites (sprites.json, 4 decimals).
constexpr DefaultAnchors kDefaults[kSpriteCount] = {
    {0.0703f, 0.4000f, 0.9609f, 0.4000f, 0.6140f},  // skull_mammal
    {0.0938f, 0.4286f, 0.9766f, 0.4286f, 0.4956f},  // skull_bird
    {0.0547f, 0.4565f, 0.9688f, 0.4565f, 0.3932f},  // skull_reptile
    {0.0391f, 0.4839f, 0.9766f, 0.4839f, 0.5167f},  // skull_fish
    {0.0469f, 0.2222f, 0.9531f, 0.2222f, 1.2414f},  // vertebra
    {0.0312f, 0.4643f, 0.9688f, 0.4643f, 0.4667f},  // tail_vertebra
    {0.0547f, 0.8056f, 0.9570f, 0.8056f, 0.3117f},  // rib
    {0.0469f, 0.5000f, 0.9219f, 0.5000f, 0.5000f},  // scapula
    {0.0469f, 0.5625f, 0.7031f, 0.5625f, 0.7619f},  // pelvis
    {0.0781f, 0.5000f, 0.9219f, 0.5000f, 0.2037f},  // long_bone
    {0.0703f, 0.2045f, 0.9062f, 0.2045f, 0.4112f},  // paw
    {0.0625f, 0.4500f, 0.9766f, 0.4500f, 0.3419f},  // hoof
    {0.1328f, 0.5000f, 0.9688f, 0.5000f, 0.2804f},  // flat_foot
    {0.0800f, 0.3000f, 0.8500f, 0.3000f, 0.6494f},  // bird_foot
    {0.0547f, 0.5417f, 0.9766f, 0.5208f, 0.2034f},  // wing_hand
    {0.0547f, 0.5000f, 0.9531f, 0.5000f, 0.8696f},  // fin
};

// The anchors must span a positive u range, and the design's width/height ratio
// r = sqrt(1/aspect² - dv²) / du must exist (see sprite_frame below).
bool anchors_consistent(glm::vec2 p, glm::vec2 c, float aspect) {
  const float du = c.x - p.x, dv = c.y - p.y;
  return du > 1e-4f && aspect > 0.0f && 1.0f / (aspect * aspect) > dv * dv + 1e-8f;
}

glm::vec2 read_anchor(JsonReader& r, const Json& sprite, const std::string& path, const char* key) {
  const Json* a = r.array(sprite, path, key);
  const std::string apath = json_path(path, key);
  if (!a) return glm::vec2(0.0f);
  if (a->size() != 2) {
    r.fail(apath, "expected [u, v], two numbers in [0, 1], got " + std::to_string(a->size()) + " values");
    return glm::vec2(0.0f);
  }
  return {static_cast<float>(r.as_number((*a)[0], json_path(apath, size_t{0}), 0.0, 1.0)),
          static_cast<float>(r.as_number((*a)[1], json_path(apath, size_t{1}), 0.0, 1.0))};
}

}  // namespace

const char* sprite_name(SpriteId id) {
  const auto i = static_cast<size_t>(id);
  return i < kSpriteCount ? kSpriteNames[i] : "unknown";
}

SpriteId sprite_id_from_name(std::string_view name) {
  for (size_t i = 0; i < kSpriteCount; ++i) {
    if (name == kSpriteNames[i]) return static_cast<SpriteId>(i);
  }
  return SpriteId::kCount;
}

SpriteSet default_sprite_set() {
  SpriteSet set;
  for (size_t i = 0; i < kSpriteCount; ++i) {
    SpriteInfo& s = set.sprites[i];
    s.name = kSpriteNames[i];
    s.file = s.name + ".png";
    s.parent_anchor = {kDefaults[i].pu, kDefaults[i].pv};
    s.child_anchor = {kDefaults[i].cu, kDefaults[i].cv};
    s.aspect = kDefaults[i].aspect;
  }
  return set;
}

Result<SpriteSet> load_sprite_set(const std::string& path) {
  Result<Json> doc = read_json_file(path);
  if (!doc.ok()) return doc.error();
  JsonReader r(path);
  const Json& root = doc.value();
  if (!r.expect_object(root, "")) return r.error();
  const std::string format = r.string(root, "", "format");
  if (!r.failed() && format != "ossa.sprites") r.fail("format", "expected \"ossa.sprites\", got \"" + format + "\"");
  r.integer(root, "", "version", 1, 1);
  const Json* sprites = r.object(root, "", "sprites");
  if (r.failed()) return r.error();

  for (auto it = sprites->begin(); it != sprites->end(); ++it) {
    if (sprite_id_from_name(it.key()) == SpriteId::kCount) {
      r.fail(json_path("sprites", it.key()), "unknown sprite name");
      return r.error();
    }
  }
  SpriteSet set;
  for (size_t i = 0; i < kSpriteCount; ++i) {
    const Json* s = r.object(*sprites, "sprites", kSpriteNames[i]);
    if (!s) return r.error();
    const std::string spath = json_path("sprites", kSpriteNames[i]);
    SpriteInfo& info = set.sprites[i];
    info.name = kSpriteNames[i];
    info.file = r.string(*s, spath, "file");
    if (!r.failed() && (info.file.size() < 5 || info.file.substr(info.file.size() - 4) != ".png" ||
                        info.file.find_first_of("/\\") != std::string::npos)) {
      r.fail(json_path(spath, "file"), "expected a .png file name without folders, got \"" + info.file + "\"");
    }
    info.parent_anchor = read_anchor(r, *s, spath, "parent_anchor");
    info.child_anchor = read_anchor(r, *s, spath, "child_anchor");
    info.aspect = r.number_f(*s, spath, "aspect", 1e-3, 100.0);
    if (r.failed()) return r.error();
    if (info.child_anchor.x <= info.parent_anchor.x + 1e-4f) {
      r.fail(json_path(spath, "child_anchor"), "expected u greater than parent_anchor's u");
    } else if (!anchors_consistent(info.parent_anchor, info.child_anchor, info.aspect)) {
      r.fail(json_path(spath, "aspect"), "expected 1 / aspect > |child v - parent v| (the anchors' distance)");
    }
    if (r.failed()) return r.error();
  }
  return set;
}

// [SECTION] Sprite choice --------------------------------------------------------------------

SpriteId sprite_for_bone(const Creature& creature, int bone) {
  const Skeleton& s = creature.skeleton;
  OSSA_ASSERT(bone >= 0 && bone < s.bone_count(), "sprite_for_bone: bone index out of range");
  switch (s.kind(bone)) {
    case BoneKind::kRoot:
    case BoneKind::kBackVertebra: return SpriteId::kVertebra;
    // Neck vertebrae are long spools with low spines, like tail vertebrae: the tall-spined
    // back vertebra stretched to a neck segment's length reads as a row of spikes.
    case BoneKind::kNeckVertebra:
    case BoneKind::kTailVertebra: return SpriteId::kTailVertebra;
    case BoneKind::kSkull:
      return static_cast<SpriteId>(static_cast<int>(SpriteId::kSkullMammal) +
                                   std::clamp(creature.skull_variant, 0, 3));
    case BoneKind::kRib: return SpriteId::kRib;
    case BoneKind::kScapula: return SpriteId::kScapula;
    case BoneKind::kPelvis: return SpriteId::kPelvis;
    case BoneKind::kUpperLimb:
    case BoneKind::kLowerLimb: return SpriteId::kLongBone;
    case BoneKind::kHand: break;
  }
  const Limb* limb = nullptr;
  for (const Limb& l : creature.limbs) {
    if (l.bones[2] == bone) limb = &l;
  }
  if (!limb) return SpriteId::kFlatFoot;
  switch (limb->kind) {
    case LimbKind::kWing: return SpriteId::kWingHand;
    case LimbKind::kFin: return SpriteId::kFin;
    case LimbKind::kArm: return SpriteId::kFlatFoot;
    case LimbKind::kLeg: break;
  }
  if (creature.count(LimbKind::kWing) > 0) return SpriteId::kBirdFoot;
  if (creature.contact == ContactMode::kFlat) return SpriteId::kFlatFoot;
  // Tip contact: the rest-pose direction of the bone is the sum of the joint angles up the
  // chain (rest locals carry no scale or mirror). Same rule as export_svg's hand_shape.
  const std::vector<BoneLocal>& locals =
      creature.rest_pose.locals.size() == static_cast<size_t>(s.bone_count()) ? creature.rest_pose.locals
                                                                             : s.rest_locals();
  float angle = 0.0f;
  for (int b = bone; b >= 0; b = s.parent(b)) angle += locals[static_cast<size_t>(b)].angle_ls;
  const float steep = std::fabs(std::sin(angle));
  if (steep < 0.5f) return SpriteId::kFlatFoot;
  const int lower = limb->bones[1];
  const bool cannon = lower >= 0 && s.length(bone) >= 0.45f * s.length(lower);
  return steep > 0.7f && cannon ? SpriteId::kHoof : SpriteId::kPaw;
}

// [SECTION] Mesh -----------------------------------------------------------------------------

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

// Maps the sprite's unit box onto a bone's frame [Z 7.4: "two offsets per bone, to the joint
// with the parent and to the joint with the child, so the placement fits whatever the size"].
// In design space (u·r, v) — height 1, width r — the anchors lie 1/aspect apart; a similarity
// takes the parent anchor to (0, 0) and the child anchor to (length, 0), then the bone's
// perpendicular axis is stretched by k so the drawn height is max(aspect·length, width).
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

SpriteFrame sprite_frame(const SpriteInfo& info, float length, float width, bool flip) {
  SpriteFrame f;
  f.p = info.parent_anchor;
  const float du = info.child_anchor.x - info.parent_anchor.x;
  const float dv = info.child_anchor.y - info.parent_anchor.y;
  const float span = 1.0f / info.aspect;  // anchor distance in design units
  f.r = std::sqrt(std::max(span * span - dv * dv, 1e-12f)) / std::max(du, 1e-6f);
  f.e = glm::vec2(du * f.r, dv) / span;
  f.sx = length / span;  // = aspect · length per design unit
  const float k = std::max(1.0f, width / std::max(info.aspect * length, 1e-12f));
  f.sy = f.sx * k * (flip ? -1.0f : 1.0f);
  return f;
}

}  // namespace

std::vector<int> chain_children(const Skeleton& s, const std::vector<BoneLocal>& locals) {
  const int n = s.bone_count();
  std::vector<int> child(static_cast<size_t>(n), -1);
  std::vector<float> turn(static_cast<size_t>(n), 0.0f);
  const auto drawn = [&](int b) { return s.length(b) > 1e-6f && std::isfinite(s.length(b)); };
  for (int c = 0; c < n; ++c) {
    const int p = s.parent(c);
    if (p < 0 || !drawn(p) || !drawn(c) || s.layer(c) != s.layer(p)) continue;
    // A girdle's flat blade meets the limb at a ball joint, not a hinge: blending would bend
    // the blade's end (the pelvis's hook, the scapula's neck) after the limb.
    if (s.kind(p) == BoneKind::kScapula || s.kind(p) == BoneKind::kPelvis) continue;
    const BoneLocal& l = locals[static_cast<size_t>(c)];
    if (glm::length(l.offset_ls - glm::vec2(s.length(p), 0.0f)) > 0.01f * s.length(p)) continue;
    const float t = std::fabs(wrap_angle(l.angle_ls));
    const auto pi = static_cast<size_t>(p);
    if (child[pi] < 0 || t < turn[pi]) child[pi] = c, turn[pi] = t;
  }
  return child;
}

namespace {

float smoothstep01(float t) {
  t = std::clamp(t, 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

// A sprite's drawn half height (metres) — the joint's thickness as the sprite shows it.
float half_height(const SpriteInfo& info, float length, float width) {
  return 0.5f * std::max(info.aspect * length, width);
}

// One blended chain joint: parent and child bones, the mid-joint palette index (-1: blend
// parent and child directly) and the blend's half width (metres along either bone).
struct JointBlend {
  int parent = -1, child = -1, mid = -1;
  float half_width = 0.0f;
};

struct BoneWeight {
  int bone = 0;
  float weight = 0.0f;
};

// The weights across `j` of a point `s` metres from the joint along its bone (negative
// toward the parent): 1 → 0 for the parent over [-half_width, half_width], through the mid
// frame when there is one (parent → mid before the joint, mid → child after it).
void joint_weights(const JointBlend& j, float s, BoneWeight out[2]) {
  const float a = j.half_width;
  if (j.mid < 0) {
    const float t = smoothstep01(0.5f + 0.5f * s / a);
    out[0] = {j.parent, 1.0f - t};
    out[1] = {j.child, t};
    return;
  }
  if (s < 0.0f) {
    const float t = smoothstep01(1.0f + s / a);
    out[0] = {j.parent, 1.0f - t};
    out[1] = {j.mid, t};
  } else {
    const float t = smoothstep01(s / a);
    out[0] = {j.mid, 1.0f - t};
    out[1] = {j.child, t};
  }
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
    const std::vector<int> chain = chain_children(s, locals);
    int mids = 0;
    for (int p = 0; p < n; ++p) {
      const int c = chain[static_cast<size_t>(p)];
      if (c < 0) continue;
      const SpriteInfo& pi = sprites[mesh.bone_sprites[static_cast<size_t>(p)]];
      const SpriteInfo& ci = sprites[mesh.bone_sprites[static_cast<size_t>(c)]];
      const float thickness = 0.5f * (half_height(pi, s.length(p), std::max(s.width(p), 0.0f)) +
                                      half_height(ci, s.length(c), std::max(s.width(c), 0.0f)));
      const float half_width =
          std::min({kSmoothBlend * thickness, kSmoothMaxSpan * s.length(p), kSmoothMaxSpan * s.length(c)});
      if (!(half_width > 0.0f) || !std::isfinite(half_width)) continue;
      JointBlend j{p, c, -1, half_width};
      if (limb_joint(c) && n + mids <= kMaxSpriteMeshBones) j.mid = n + mids++;
      end_blend[static_cast<size_t>(p)] = j;
      start_blend[static_cast<size_t>(c)] = j;
      bind_locals[static_cast<size_t>(c)].angle_ls = 0.0f;
    }
  }
  const std::vector<Mat2x3> model = smooth ? model_matrices(s, bind_locals) : rest;
  mesh.inverse_bind.reserve(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) mesh.inverse_bind.push_back(inverse(model[static_cast<size_t>(i)]));
  for (const JointBlend& j : end_blend) {
    if (j.mid < 0) continue;
    const Mat2x3 bind = mid_joint_frame(model[static_cast<size_t>(j.parent)], model[static_cast<size_t>(j.child)]);
    mesh.mid_joints.push_back({j.parent, j.child, inverse(bind)});
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

  mesh.vertices.reserve(order.size() * (smooth ? 24 : 8));
  mesh.indices.reserve(order.size() * (smooth ? 66 : 18));
  std::vector<float> columns;
  int layer = 0;
  for (int bone : order) {
    const int bone_layer = static_cast<int>(s.layer(bone));
    while (layer < bone_layer) mesh.layer_begin[static_cast<size_t>(++layer)] = static_cast<uint32_t>(mesh.indices.size());

    const SpriteInfo& info = sprites[mesh.bone_sprites[static_cast<size_t>(bone)]];
    const SpriteFrame frame = sprite_frame(info, s.length(bone), std::max(s.width(bone), 0.0f), s.sprite_flip_y(bone));
    const Mat2x3& m = model[static_cast<size_t>(bone)];
    const float shade = s.layer(bone) == Layer::kFar ? options.far_shade : 1.0f;
    const float pu = info.parent_anchor.x, cu = info.child_anchor.x;
    const float metres_per_u = s.length(bone) / (cu - pu);  // along the bone
    const JointBlend& at_start = start_blend[static_cast<size_t>(bone)];
    const JointBlend& at_end = end_blend[static_cast<size_t>(bone)];

    // Columns: the sprite's ends and both anchors; around each blended joint kSmoothColumns
    // more on either side, evenly over the blend (those on the sprite).
    columns.assign({0.0f, pu, cu, 1.0f});
    for (const auto& [j, joint_u] : {std::pair{&at_start, pu}, std::pair{&at_end, cu}}) {
      if (j->parent < 0) continue;
      // Limb joints turn far (finer columns); spine joints a few degrees each.
      const int per_side = j->mid >= 0 ? kSmoothColumns : kSmoothSpineColumns;
      for (int k = -per_side; k <= per_side; ++k) {
        const float u = joint_u + j->half_width / metres_per_u * static_cast<float>(k) / per_side;
        if (u > 0.0f && u < 1.0f) columns.push_back(u);
      }
    }
    std::sort(columns.begin(), columns.end());
    columns.erase(std::unique(columns.begin(), columns.end(), [](float a, float b) { return b - a < 1e-5f; }),
                  columns.end());

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
      for (float v : {0.0f, 1.0f}) {
        SpriteVertex vert;
        vert.position_ms = m.apply(frame.map({u, v}));
        vert.uv = info.uv_min + glm::vec2(u, 1.0f - v) * (info.uv_max - info.uv_min);
        vert.bones = bones;
        vert.weights = weights;
        vert.shade = shade;
        mesh.vertices.push_back(vert);
      }
    }
    for (uint32_t c = 0; c + 1 < columns.size(); ++c) {
      const uint32_t a = first + 2 * c;  // (u_c, 0), (u_c, 1), then c+1
      mesh.indices.insert(mesh.indices.end(), {a, a + 2, a + 3, a, a + 3, a + 1});
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

glm::vec2 skin_vertex(const SpriteVertex& v, std::span<const Mat2x3> palette) {
  glm::vec2 p(0.0f);
  for (size_t k = 0; k < 4; ++k) {
    if (v.weights[k] != 0.0f) p += v.weights[k] * palette[v.bones[k]].apply(v.position_ms);
  }
  return p;
}

Mat2x3 mid_joint_frame(const Mat2x3& parent, const Mat2x3& child) {
  // The child's turn relative to the parent: L_p⁻¹ L_c is a rotation (any common scale or
  // mirror cancels); its half angle is the unit complex sqrt(z) = normalise(1 + z).
  const float a = parent.m[0], b = parent.m[1], c = parent.m[2], d = parent.m[3];
  const float det = a * d - b * c;
  glm::vec2 z(1.0f, 0.0f);
  if (std::fabs(det) > 1e-20f) {
    z = glm::vec2(d * child.m[0] - c * child.m[1], -b * child.m[0] + a * child.m[1]) / det;
  }
  glm::vec2 half(1.0f + z.x, z.y);
  const float len = glm::length(half);
  half = len > 1e-6f * (1.0f + glm::length(z)) ? half / len : glm::vec2(0.0f, 1.0f);  // a half turn: 90°
  Mat2x3 turn;
  turn.m[0] = half.x, turn.m[1] = half.y, turn.m[2] = -half.y, turn.m[3] = half.x;
  Mat2x3 mid = parent * turn;
  mid.m[4] = child.m[4];
  mid.m[5] = child.m[5];
  return mid;
}

void mid_joint_palette(std::span<const MidJoint> mid_joints, std::span<const Mat2x3> world,
                       std::span<Mat2x3> palette) {
  const size_t bones = world.size();
  OSSA_ASSERT(palette.size() == bones + mid_joints.size(), "mid_joint_palette: one entry per bone and mid joint");
  for (size_t i = 0; i < mid_joints.size(); ++i) {
    const MidJoint& j = mid_joints[i];
    palette[bones + i] = mid_joint_frame(world[static_cast<size_t>(j.parent)], world[static_cast<size_t>(j.child)]) *
                         j.inverse_bind;
  }
}

int max_weights_per_vertex(const SpriteMesh& mesh) {
  int most = 0;
  for (const SpriteVertex& v : mesh.vertices) {
    int count = 0;
    for (float w : v.weights) count += w > 0.0f;
    most = std::max(most, count);
  }
  return most;
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
