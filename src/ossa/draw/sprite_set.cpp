#include "ossa/draw/sprite_mesh.h"

// The bone sprite set: sprite names, the built-in anchors, the sprites.json loader and the
// measured joint reach (sprite_mesh.h).

#include <string>

#include "ossa/io/json.h"

namespace ossa {
namespace {

constexpr size_t kSpriteCount = static_cast<size_t>(SpriteId::kCount);

constexpr const char* kSpriteNames[kSpriteCount] = {
    "skull_mammal", "skull_bird", "skull_reptile", "skull_fish", "vertebra", "tail_vertebra",
    "rib",          "scapula",    "pelvis",        "long_bone",  "paw",      "hoof",
    "flat_foot",    "bird_foot",  "wing_hand",     "fin"};


struct DefaultAnchors {
  float pu, pv, cu, cv, aspect, thickness, contact_from, snout_from;
};
// Measured from the SVG sources by tools/make-bone-sprites (sprites.json, 4 decimals; 0 and -1:
// not given).
constexpr DefaultAnchors kDefaults[kSpriteCount] = {
    {0.0703f, 0.4000f, 0.9609f, 0.4000f, 0.6140f, 0.8700f, -1.0000f, 0.5469f},  // skull_mammal
    {0.0938f, 0.4286f, 0.9766f, 0.4286f, 0.4956f, 0.8000f, -1.0000f, 0.3906f},  // skull_bird
    {0.0547f, 0.4565f, 0.9688f, 0.4565f, 0.3932f, 0.7600f, -1.0000f, 0.3125f},  // skull_reptile
    {0.0391f, 0.4839f, 0.9766f, 0.4839f, 0.5167f, 0.8700f, -1.0000f, 0.5859f},  // skull_fish
    {0.0469f, 0.2222f, 0.9531f, 0.2222f, 1.2414f, 0.7000f, -1.0000f, -1.0000f},  // vertebra
    {0.0312f, 0.4643f, 0.9688f, 0.4643f, 0.4667f, 0.6000f, -1.0000f, -1.0000f},  // tail_vertebra
    {0.0547f, 0.8056f, 0.9570f, 0.8056f, 0.3117f, 0.0000f, -1.0000f, -1.0000f},  // rib
    {0.0469f, 0.5000f, 0.9219f, 0.5000f, 0.5000f, 0.8500f, -1.0000f, -1.0000f},  // scapula
    {0.0469f, 0.5625f, 0.7031f, 0.5625f, 0.7619f, 0.8500f, -1.0000f, -1.0000f},  // pelvis
    {0.0781f, 0.5000f, 0.9219f, 0.5000f, 0.2037f, 0.6800f, -1.0000f, -1.0000f},  // long_bone
    {0.0703f, 0.2045f, 0.9766f, 0.2045f, 0.3793f, 0.2500f, 0.8359f, -1.0000f},  // paw
    {0.0625f, 0.4500f, 0.9961f, 0.4500f, 0.3347f, 0.3000f, 0.7812f, -1.0000f},  // hoof
    {0.0234f, 0.1317f, 0.9922f, 0.3967f, 0.2414f, 0.5500f, -1.0000f, -1.0000f},  // flat_foot
    {0.0800f, 0.3000f, 0.9950f, 0.3000f, 0.5464f, 0.2200f, 0.7200f, -1.0000f},  // bird_foot
    {0.0547f, 0.5417f, 0.9766f, 0.5208f, 0.2034f, 0.4200f, -1.0000f, -1.0000f},  // wing_hand
    {0.0547f, 0.5000f, 0.9531f, 0.5000f, 0.8696f, 0.0000f, -1.0000f, -1.0000f},  // fin
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
    s.thickness = kDefaults[i].thickness;
    s.contact_from = kDefaults[i].contact_from;
    s.snout_from = kDefaults[i].snout_from;
  }
  return set;
}

glm::vec2 joint_reach(const SpriteInfo& info, bool child_end) {
  const glm::vec2 measured = child_end ? info.child_reach : info.parent_reach;
  if (measured.x >= 0.0f && measured.y >= 0.0f) return measured;
  const float v = child_end ? info.child_anchor.y : info.parent_anchor.y;
  return {v, 1.0f - v};
}

Result<SpriteSet> load_sprite_set(const std::string& path) {
  Result<Json> doc = read_json_file(path);
  if (!doc.ok()) return doc.error();
  JsonReader r(path);
  const Json& root = doc.value();
  if (!r.expect_object(root, "")) return r.error();
  const std::string format = r.string(root, "", "format");
  if (!r.failed() && format != "ossa.sprites") r.fail("format", "expected \"ossa.sprites\", got \"" + format + "\"");
  const long long version = r.integer(root, "", "version", 1, 2);
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
    // Version 2: how the width, a foot's contact part and a skull's muzzle map (sprite_mesh.h).
    for (const char* key : {"thickness", "contact_from", "snout_from"}) {
      if (version < 2 && r.has(*s, key)) r.fail(json_path(spath, key), "needs version 2");
    }
    info.thickness = static_cast<float>(r.number_or(*s, spath, "thickness", 0.0, 1e-3, 1.0));
    const double pu = info.parent_anchor.x, cu = info.child_anchor.x;
    info.contact_from = static_cast<float>(r.number_or(*s, spath, "contact_from", -1.0, pu, cu));
    info.snout_from = static_cast<float>(r.number_or(*s, spath, "snout_from", -1.0, pu, cu));
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

}  // namespace ossa
