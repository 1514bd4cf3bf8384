#include "ossa/gen/look.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/common.hpp>

#include "ossa/io/json.h"
#include "ossa/math/rng.h"

namespace ossa {

namespace {

constexpr const char* kAppendageNames[kAppendageKindCount] = {
    "ears", "horns", "antlers", "frill", "crest", "mane", "trunk",
    "hump", "sail",  "plates",  "shell", "dorsal_fin", "tail_fin"};
constexpr const char* kPatternNames[kCoatPatternCount] = {"none",    "stripes", "spots",
                                                          "rosettes", "dapples", "patches"};

glm::vec3 rgb(int hex) {
  return {static_cast<float>((hex >> 16) & 0xff) / 255.0f, static_cast<float>((hex >> 8) & 0xff) / 255.0f,
          static_cast<float>(hex & 0xff) / 255.0f};
}

// A coat: base, belly and pattern colour (sRGB hex), as real animals of the kind wear them.
struct Palette {
  int base, belly, pattern;
};
constexpr Palette kMammal[] = {
    {0x8a5a3c, 0xd8c3a0, 0x3b2618},  // bay brown
    {0x9c7a52, 0xe2d3b5, 0x4a3522},  // fawn
    {0x6f6a64, 0xbfb8ad, 0x2e2b28},  // grey
    {0xb3844f, 0xeadbbd, 0x3a2a18},  // tawny
    {0x4a3b31, 0x8f7b68, 0x1e1712},  // dark brown
    {0xa9a198, 0xe8e3da, 0x5c554c},  // pale grey
    {0x7d4e2d, 0xcfae86, 0x2a1a10},  // chestnut
    {0xc9b08a, 0xf1e8d6, 0x6b5236},  // sand
};
constexpr Palette kBird[] = {
    {0x5e6670, 0xd9dde0, 0x22262b},  // grey, white breast
    {0x7b5a3a, 0xd6c3a3, 0x33241a},  // brown
    {0x262a30, 0xe9ecee, 0x0e1013},  // black and white
    {0x8c8f7a, 0xe0dccb, 0x3f4236},  // olive grey
    {0xb9b3a8, 0xf4f1ea, 0x55504a},  // pale
};
constexpr Palette kReptile[] = {
    {0x5f6b3c, 0xc7c49a, 0x2c331a},  // olive
    {0x6e5a3e, 0xcdbb93, 0x2f2417},  // brown
    {0x4f6e4a, 0xc2d0a4, 0x223320},  // green
    {0x7c7463, 0xd2cab2, 0x3a352b},  // stone
    {0x8a6f45, 0xdcc89a, 0x3d2c17},  // ochre
};
constexpr Palette kFish[] = {
    {0x56707e, 0xdfe7ea, 0x26343c},  // blue-grey, silver belly
    {0x6b7a52, 0xe3e4c8, 0x2f3a22},  // olive, pale belly
    {0x4c5d6e, 0xd5dde4, 0x1f2a35},  // slate
    {0x7c8a8e, 0xeef2f2, 0x3b4548},  // silver
};

template <size_t N>
const Palette& pick(const Palette (&list)[N], Rng& rng) {
  return list[static_cast<size_t>(rng.uniform_int(0, static_cast<int>(N) - 1))];
}

// `c` with each channel moved by up to ±amount (a little individual variation).
glm::vec3 vary(glm::vec3 c, Rng& rng, float amount) {
  const float k = 1.0f + static_cast<float>(rng.uniform(-amount, amount));
  return glm::clamp(c * k, glm::vec3(0.0f), glm::vec3(1.0f));
}

}  // namespace

const char* appendage_kind_name(AppendageKind kind) {
  const auto i = static_cast<size_t>(kind);
  return i < kAppendageKindCount ? kAppendageNames[i] : "unknown";
}

std::optional<AppendageKind> appendage_kind_from_name(std::string_view name) {
  for (int i = 0; i < kAppendageKindCount; ++i) {
    if (name == kAppendageNames[i]) return static_cast<AppendageKind>(i);
  }
  return std::nullopt;
}

const char* coat_pattern_name(CoatPattern pattern) {
  const auto i = static_cast<size_t>(pattern);
  return i < kCoatPatternCount ? kPatternNames[i] : "unknown";
}

std::optional<CoatPattern> coat_pattern_from_name(std::string_view name) {
  for (int i = 0; i < kCoatPatternCount; ++i) {
    if (name == kPatternNames[i]) return static_cast<CoatPattern>(i);
  }
  return std::nullopt;
}

const char* wing_cover_name(WingCover cover) { return cover == WingCover::kMembrane ? "membrane" : "feathered"; }

std::string colour_hex(glm::vec3 c) {
  const auto byte = [](float v) {
    const float x = std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 0.0f;
    return static_cast<int>(std::lround(x * 255.0f));
  };
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", byte(c.r), byte(c.g), byte(c.b));
  return buf;
}

std::optional<glm::vec3> colour_from_hex(std::string_view text) {
  if (text.size() != 7 || text[0] != '#') return std::nullopt;
  int v = 0;
  for (size_t i = 1; i < 7; ++i) {
    const char ch = text[i];
    int d;
    if (ch >= '0' && ch <= '9') d = ch - '0';
    else if (ch >= 'a' && ch <= 'f') d = ch - 'a' + 10;
    else if (ch >= 'A' && ch <= 'F') d = ch - 'A' + 10;
    else return std::nullopt;
    v = v * 16 + d;
  }
  return rgb(v);
}

Look random_look(uint64_t seed, int skull_variant, bool winged) {
  // Its own stream: drawing the look never shifts the genome's other choices.
  Rng rng(seed ^ 0x6c6f6f6b2d763031ull);  // "look-v01"
  // Winged bodies with a bird's skull are birds; wings on another skull are a bat's or a
  // pterosaur's membrane, coloured like the rest of that kind.
  const int kind = std::clamp(skull_variant, 0, 3);
  const Palette& p = kind == 1 ? pick(kBird, rng) : kind == 2 ? pick(kReptile, rng) : kind == 3 ? pick(kFish, rng)
                                                                                            : pick(kMammal, rng);
  Look look;
  look.base = vary(rgb(p.base), rng, 0.08f);
  look.belly = vary(rgb(p.belly), rng, 0.05f);
  look.pattern_colour = vary(rgb(p.pattern), rng, 0.1f);
  // Patterns where the kind wears them: mammals stripes, spots, rosettes, dapples, patches;
  // reptiles and fish bands and spots; birds plain (their pattern is in the feathers).
  const double u = rng.uniform();
  switch (kind) {
    case 0:
      look.pattern = u < 0.55 ? CoatPattern::kNone
                     : u < 0.65 ? CoatPattern::kStripes
                     : u < 0.75 ? CoatPattern::kSpots
                     : u < 0.83 ? CoatPattern::kRosettes
                     : u < 0.93 ? CoatPattern::kDapples
                                : CoatPattern::kPatches;
      break;
    case 2: look.pattern = u < 0.5 ? CoatPattern::kNone : u < 0.75 ? CoatPattern::kStripes : CoatPattern::kSpots; break;
    case 3: look.pattern = u < 0.6 ? CoatPattern::kNone : u < 0.8 ? CoatPattern::kStripes : CoatPattern::kSpots; break;
    default: look.pattern = CoatPattern::kNone; break;
  }
  look.pattern_scale = static_cast<float>(rng.uniform(0.07, 0.2));
  look.fatness = static_cast<float>(rng.uniform(0.9, 1.1));
  look.wings = winged && kind != 1 ? WingCover::kMembrane : WingCover::kFeathered;
  return look;
}

Json look_to_json(const Look& l) {
  return Json{{"base", colour_hex(l.base)},
              {"belly", colour_hex(l.belly)},
              {"pattern", coat_pattern_name(l.pattern)},
              {"pattern_colour", colour_hex(l.pattern_colour)},
              {"pattern_scale", json_float(l.pattern_scale)},
              {"fatness", json_float(l.fatness)},
              {"wings", wing_cover_name(l.wings)}};
}

Json appendages_to_json(const std::vector<Appendage>& appendages) {
  Json list = Json::array();
  for (const Appendage& a : appendages) list.push_back({{"kind", appendage_kind_name(a.kind)}, {"size", json_float(a.size)}});
  return list;
}

namespace {

glm::vec3 read_colour(JsonReader& r, const Json& o, const std::string& path, const char* key, glm::vec3 fallback) {
  if (!r.has(o, key)) return fallback;
  const std::string text = r.string(o, path, key);
  if (r.failed()) return fallback;
  if (const auto c = colour_from_hex(text)) return *c;
  r.fail(json_path(path, key), "expected a colour \"#rrggbb\" (six hex digits), got \"" + text + "\"");
  return fallback;
}

}  // namespace

void read_look(JsonReader& r, const Json& parent, std::string_view parent_path, std::string_view key, Look& out) {
  const Json* o = r.object(parent, parent_path, key);
  if (!o) return;
  const std::string path = json_path(parent_path, key);
  static constexpr const char* kKeys[] = {"base", "belly", "pattern", "pattern_colour", "pattern_scale", "fatness", "wings"};
  for (auto it = o->begin(); it != o->end(); ++it) {
    if (std::find_if(std::begin(kKeys), std::end(kKeys), [&](const char* k) { return it.key() == k; }) == std::end(kKeys)) {
      r.fail(json_path(path, it.key()), "unknown field (expected base, belly, pattern, pattern_colour, "
                                        "pattern_scale, fatness or wings)");
      return;
    }
  }
  Look l = out;
  l.base = read_colour(r, *o, path, "base", l.base);
  l.belly = read_colour(r, *o, path, "belly", l.belly);
  l.pattern_colour = read_colour(r, *o, path, "pattern_colour", l.pattern_colour);
  const std::string pattern = r.string_or(*o, path, "pattern", coat_pattern_name(l.pattern));
  if (!r.failed()) {
    if (const auto p = coat_pattern_from_name(pattern)) {
      l.pattern = *p;
    } else {
      r.fail(json_path(path, "pattern"),
             "expected \"none\", \"stripes\", \"spots\", \"rosettes\", \"dapples\" or \"patches\", got \"" + pattern + "\"");
    }
  }
  l.pattern_scale = static_cast<float>(r.number_or(*o, path, "pattern_scale", l.pattern_scale, json_float(kMinPatternScale), json_float(kMaxPatternScale)));
  l.fatness = static_cast<float>(r.number_or(*o, path, "fatness", l.fatness, json_float(kMinFatness), json_float(kMaxFatness)));
  const std::string wings = r.string_or(*o, path, "wings", wing_cover_name(l.wings));
  if (!r.failed()) {
    if (wings == "feathered") l.wings = WingCover::kFeathered;
    else if (wings == "membrane") l.wings = WingCover::kMembrane;
    else r.fail(json_path(path, "wings"), "expected \"feathered\" or \"membrane\", got \"" + wings + "\"");
  }
  if (!r.failed()) out = l;
}

void read_appendages(JsonReader& r, const Json& parent, std::string_view parent_path, std::string_view key,
                     std::vector<Appendage>& out) {
  const Json* list = r.array(parent, parent_path, key);
  if (!list) return;
  const std::string path = json_path(parent_path, key);
  if (list->size() > static_cast<size_t>(kAppendageKindCount)) {
    r.fail(path, "expected at most " + std::to_string(kAppendageKindCount) + " appendages (one of each kind), got " +
                     std::to_string(list->size()));
    return;
  }
  std::vector<Appendage> result;
  for (size_t i = 0; i < list->size() && !r.failed(); ++i) {
    const std::string ipath = json_path(path, i);
    const Json& a = (*list)[i];
    if (!r.expect_object(a, ipath)) break;
    Appendage app;
    const std::string kind = r.string(a, ipath, "kind");
    if (r.failed()) break;
    const auto k = appendage_kind_from_name(kind);
    if (!k) {
      std::string names;
      for (int n = 0; n < kAppendageKindCount; ++n) names += std::string(n ? ", " : "") + kAppendageNames[n];
      r.fail(json_path(ipath, "kind"), "expected one of " + names + ", got \"" + kind + "\"");
      break;
    }
    app.kind = *k;
    app.size = static_cast<float>(r.number_or(a, ipath, "size", 1.0, json_float(kMinAppendageSize), json_float(kMaxAppendageSize)));
    for (const Appendage& before : result) {
      if (before.kind == app.kind) r.fail(json_path(ipath, "kind"), "expected each kind once, but \"" + kind + "\" is given twice");
    }
    result.push_back(app);
  }
  if (!r.failed()) out = std::move(result);
}

void clamp_look(Look& l) {
  const auto clamp = [](float v, float lo, float hi) { return v >= lo ? (v <= hi ? v : hi) : lo; };  // NaN → lo
  for (glm::vec3* c : {&l.base, &l.belly, &l.pattern_colour}) {
    for (int i = 0; i < 3; ++i) (*c)[i] = clamp((*c)[i], 0.0f, 1.0f);
  }
  l.pattern_scale = clamp(l.pattern_scale, kMinPatternScale, kMaxPatternScale);
  l.fatness = clamp(l.fatness, kMinFatness, kMaxFatness);
  if (static_cast<int>(l.pattern) >= kCoatPatternCount) l.pattern = CoatPattern::kNone;
}

void clamp_appendages(std::vector<Appendage>& appendages) {
  std::vector<Appendage> kept;
  for (Appendage a : appendages) {
    if (static_cast<int>(a.kind) >= kAppendageKindCount) continue;
    if (std::any_of(kept.begin(), kept.end(), [&](const Appendage& k) { return k.kind == a.kind; })) continue;
    a.size = a.size >= kMinAppendageSize ? std::min(a.size, kMaxAppendageSize) : kMinAppendageSize;
    kept.push_back(a);
  }
  appendages = std::move(kept);
}

}  // namespace ossa
