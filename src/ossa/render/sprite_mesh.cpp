#include "ossa/render/sprite_mesh.h"

// Sections:
//   [SECTION] Sprite set — names, built-in anchors, sprites.json loader
//   [SECTION] Sprite choice — BoneKind + limb + contact + skull variant → SpriteId
//   [SECTION] Mesh — anchor mapping [Z 7.4], strips, weights, layers

#include <algorithm>
#include <cmath>

#include "ossa/io/json.h"
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
  const std::vector<Mat2x3> model = model_matrices(s, locals);

  SpriteMesh mesh;
  mesh.inverse_bind.reserve(static_cast<size_t>(n));
  mesh.bone_sprites.reserve(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    mesh.inverse_bind.push_back(inverse(model[static_cast<size_t>(i)]));
    mesh.bone_sprites.push_back(sprite_for_bone(creature, i));
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

  mesh.vertices.reserve(order.size() * 10);
  mesh.indices.reserve(order.size() * 24);
  int layer = 0;
  for (int bone : order) {
    const int bone_layer = static_cast<int>(s.layer(bone));
    while (layer < bone_layer) mesh.layer_begin[static_cast<size_t>(++layer)] = static_cast<uint32_t>(mesh.indices.size());

    const SpriteInfo& info = sprites[mesh.bone_sprites[static_cast<size_t>(bone)]];
    const SpriteFrame frame = sprite_frame(info, s.length(bone), std::max(s.width(bone), 0.0f), s.sprite_flip_y(bone));
    const Mat2x3& m = model[static_cast<size_t>(bone)];
    const float shade = s.layer(bone) == Layer::kFar ? options.far_shade : 1.0f;
    const int parent = s.parent(bone);

    // Columns: the sprite's ends, both anchors and the end of the smooth-weight fade.
    const float pu = info.parent_anchor.x, cu = info.child_anchor.x;
    const float fade_u = pu + kSmoothSpan * (cu - pu);
    float columns[5] = {0.0f, pu, fade_u, cu, 1.0f};
    int count = 0;
    for (float u : columns) {
      if (count == 0 || u > columns[count - 1] + 1e-5f) columns[count++] = u;
    }
    const auto first = static_cast<uint32_t>(mesh.vertices.size());
    for (int c = 0; c < count; ++c) {
      const float u = columns[c];
      // Smooth weights: 50/50 with the parent at and behind the joint, the bone alone from
      // fade_u on — a joint then bends the overlap like a hinge instead of two rigid cards.
      float w_self = 1.0f;
      if (options.smooth_weights && parent >= 0) {
        w_self = std::clamp(0.5f + 0.5f * (u - pu) / std::max(fade_u - pu, 1e-6f), 0.5f, 1.0f);
      }
      for (float v : {0.0f, 1.0f}) {
        SpriteVertex vert;
        vert.position_ms = m.apply(frame.map({u, v}));
        vert.uv = info.uv_min + glm::vec2(u, 1.0f - v) * (info.uv_max - info.uv_min);
        vert.bones = {static_cast<uint8_t>(bone), 0, 0, 0};
        vert.weights = {w_self, 0.0f, 0.0f, 0.0f};
        if (w_self < 1.0f) {
          vert.bones[1] = static_cast<uint8_t>(parent);
          vert.weights[1] = 1.0f - w_self;
        }
        vert.shade = shade;
        mesh.vertices.push_back(vert);
      }
    }
    for (int c = 0; c + 1 < count; ++c) {
      const uint32_t a = first + 2 * static_cast<uint32_t>(c);  // (u_c, 0), (u_c, 1), then c+1
      mesh.indices.insert(mesh.indices.end(), {a, a + 2, a + 3, a, a + 3, a + 1});
    }
  }
  while (layer < kLayerCount) mesh.layer_begin[static_cast<size_t>(++layer)] = static_cast<uint32_t>(mesh.indices.size());
  mesh.layer_begin[0] = 0;
  return mesh;
}

Box sprite_mesh_bounds(const SpriteMesh& mesh) {
  if (mesh.vertices.empty()) return Box{};
  Box b{mesh.vertices.front().position_ms, mesh.vertices.front().position_ms};
  for (const SpriteVertex& v : mesh.vertices) {
    b.min_ws = glm::min(b.min_ws, v.position_ms);
    b.max_ws = glm::max(b.max_ws, v.position_ms);
  }
  return b;
}

}  // namespace ossa
