#include "ossa/gen/export_svg.h"

// Sections:
//   [SECTION] Path builder — SVG path data in a bone's local frame, with its bounds
//   [SECTION] Bone shapes — one function per bone kind [Z 7.4]
//   [SECTION] Creature drawing — layers, ground, viewBox
//   [SECTION] Documents — creature_svg, sheet_svg

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include <glm/geometric.hpp>

#include "ossa/skeleton/pose.h"

namespace ossa {
namespace {


// [SECTION] Path builder ---------------------------------------------------------------------

// Shortest round-trip-ish text of a finite float ("%.5g" keeps five significant digits, enough
// for a drawing at any scale; SVG accepts the exponent form).
void append_num(std::string& out, float v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.5g", static_cast<double>(v));
  out += buf;
}

std::string num(float v) {
  std::string s;
  append_num(s, v);
  return s;
}

struct Bounds {
  glm::vec2 lo{std::numeric_limits<float>::max()};
  glm::vec2 hi{std::numeric_limits<float>::lowest()};
  void add(glm::vec2 p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  bool empty() const { return lo.x > hi.x; }
};

// Builds path data. `flip` rotates the shape by 180° about (flip_len / 2, 0): a shape authored
// for a headward bone (+x to the head, +y dorsal) then fits a tailward one.
class PathBuilder {
 public:
  explicit PathBuilder(bool flip = false, float flip_len = 0.0f) : flip_(flip), len_(flip_len) {}

  void move(glm::vec2 p) { cmd('M', {p}); }
  void line(glm::vec2 p) { cmd('L', {p}); }
  void quad(glm::vec2 c, glm::vec2 p) { cmd('Q', {c, p}); }
  void cubic(glm::vec2 c1, glm::vec2 c2, glm::vec2 p) { cmd('C', {c1, c2, p}); }
  // Circular arc of radius r about `center` to p (the center only feeds the bounds).
  void arc(float r, bool large, bool sweep, glm::vec2 p, glm::vec2 center) {
    d_ += 'A';
    append_num(d_, r);
    d_ += ' ';
    append_num(d_, r);
    d_ += large ? " 0 1 " : " 0 0 ";
    d_ += sweep ? "1 " : "0 ";
    point(p);
    const glm::vec2 c = map(center);
    points_.push_back(c + glm::vec2(r, r));
    points_.push_back(c - glm::vec2(r, r));
  }
  void close() { d_ += "Z"; }

  // Closed shapes.
  void circle(glm::vec2 c, float r) {
    move(c + glm::vec2(r, 0.0f));
    arc(r, true, true, c - glm::vec2(r, 0.0f), c);
    arc(r, true, true, c + glm::vec2(r, 0.0f), c);
    close();
  }
  // A tapered capsule from a (radius ra) to b (radius rb).
  void capsule(glm::vec2 a, glm::vec2 b, float ra, float rb) {
    glm::vec2 dir = b - a;
    const float len = std::sqrt(dir.x * dir.x + dir.y * dir.y);
    dir = len > 1e-12f ? dir / len : glm::vec2(1.0f, 0.0f);
    const glm::vec2 n(-dir.y, dir.x);
    move(a + n * ra);
    line(b + n * rb);
    arc(rb, false, false, b - n * rb, b);
    line(a - n * ra);
    arc(ra, false, false, a + n * ra, a);
    close();
  }
  void polygon(std::initializer_list<glm::vec2> pts) {
    bool first = true;
    for (glm::vec2 p : pts) {
      if (first) move(p); else line(p);
      first = false;
    }
    close();
  }

  const std::string& data() const { return d_; }
  const std::vector<glm::vec2>& points() const { return points_; }
  bool empty() const { return d_.empty(); }

 private:
  glm::vec2 map(glm::vec2 p) const { return flip_ ? glm::vec2(len_ - p.x, -p.y) : p; }
  void point(glm::vec2 p) {
    p = map(p);
    append_num(d_, p.x);
    d_ += ' ';
    append_num(d_, p.y);
    points_.push_back(p);
  }
  void cmd(char c, std::initializer_list<glm::vec2> pts) {
    d_ += c;
    bool first = true;
    for (glm::vec2 p : pts) {
      if (!first) d_ += ' ';
      point(p);
      first = false;
    }
  }

  bool flip_;
  float len_;
  std::string d_;
  std::vector<glm::vec2> points_;
};

// [SECTION] Bone shapes ----------------------------------------------------------------------

// What the shape functions need to know about one bone besides its size.
struct BoneContext {
  float length = 0.0f;
  float width = 0.0f;
  bool headward = true;            // spine bones: +x points to the head (dorsal is +y)
  glm::vec2 forward_ls{1.0f, 0.0f};  // model +x (the creature's forward) in the bone frame
  glm::vec2 up_ls{0.0f, 1.0f};       // model +y in the bone frame
};

// Long bone: shaft with a waist and rounded knobs at both joints.
void long_bone(PathBuilder& p, float L, float w) {
  const float re = std::clamp(0.5f * w, 0.04f * L, 0.3f * L);  // knob radius
  const float hs = 0.45f * re;                                  // shaft half-width
  const float a0 = 0.75f * re;                                  // knob centres, inset
  const float a1 = L - 0.8f * re;
  const float r1 = 0.9f * re;
  const float s0 = std::sqrt(re * re - hs * hs);
  const float s1 = std::sqrt(r1 * r1 - hs * hs);
  const float x0 = a0 + s0, x1 = a1 - s1;
  const float waist = 0.75f * hs;
  p.move({x0, hs});
  p.cubic({x0 + 0.3f * (x1 - x0), waist}, {x1 - 0.3f * (x1 - x0), waist}, {x1, hs});
  p.arc(r1, true, false, {x1, -hs}, {a1, 0.0f});
  p.cubic({x1 - 0.3f * (x1 - x0), -waist}, {x0 + 0.3f * (x1 - x0), -waist}, {x0, -hs});
  p.arc(re, true, false, {x0, hs}, {a0, 0.0f});
  p.close();
}

// Vertebra, authored headward: body, spinous process leaning to the tail (-x), transverse
// process as a small ventral-caudal lobe.
void vertebra(PathBuilder& p, float L, float w, float spine_height) {
  // Bodies at least 0.3 L high and nearly touching, so the column reads as one spine.
  const float h = 0.5f * std::clamp(w, 0.3f * L, 1.5f * L);
  const float x0 = 0.03f * L, x1 = 0.97f * L;
  const float top = 0.55f * h, bot = -0.55f * h;
  const float r = 0.25f * h;
  p.move({x0, bot + r});
  p.line({x0, top - r});
  p.quad({x0, top}, {x0 + r, top});
  // Spinous process: rises from the middle, tip leaning back.
  const float sp = spine_height;
  p.line({0.3f * L, top});
  p.line({0.22f * L - 0.25f * sp, top + sp});
  p.line({0.42f * L - 0.25f * sp, top + sp});
  p.line({0.62f * L, top});
  p.line({x1 - r, top});
  p.quad({x1, top}, {x1, top - r});
  p.line({x1, bot + r});
  p.quad({x1, bot}, {x1 - r, bot});
  p.line({x0 + r, bot});
  p.quad({x0, bot}, {x0, bot + r});
  p.close();
  // Transverse process.
  p.capsule({0.55f * L, -0.05f * h}, {0.2f * L, -0.35f * h}, 0.16f * h, 0.1f * h);
}

// Rib: a tapered arc bulging to side `bulge` (+1: +y).
void rib(PathBuilder& p, float L, float w, float bulge) {
  const float h = 0.5f * std::clamp(w, 0.02f * L, 0.25f * L);
  const float b = bulge * 0.22f * L;
  p.move({0.0f, h});
  p.quad({0.5f * L, b + 0.6f * h}, {L, 0.25f * h});
  p.arc(0.25f * h, false, false, {L, -0.25f * h}, {L, 0.0f});
  p.quad({0.5f * L, b - 0.6f * h}, {0.0f, -h});
  p.close();
}

// Skull, authored with the snout at +x and the dorsal side at +y. Holes (orbit, nostril) go
// to `holes`.
void skull(PathBuilder& p, PathBuilder& holes, float L, float w, int variant) {
  const float H = std::clamp(w, 0.2f * L, 1.0f * L);
  switch (variant) {
    case 1: {  // bird: round cranium, long beak
      const float r = std::min(0.3f * L, 0.55f * H);
      const glm::vec2 c(0.3f * L, 0.1f * H);
      p.move({c.x, c.y + r});
      p.cubic({c.x + 0.4f * r, c.y + r}, {0.7f * L, 0.05f * H}, {L, -0.12f * H});
      p.cubic({0.8f * L, -0.12f * H}, {0.6f * L, -0.18f * H}, {c.x + 0.6f * r, c.y - 0.75f * r});
      p.arc(r, true, false, {c.x, c.y + r}, c);
      p.close();
      holes.circle({c.x + 0.15f * r, c.y + 0.15f * r}, 0.38f * r);
      break;
    }
    case 2: {  // reptile: long and flat, long jaw
      p.move({0.0f, 0.0f});
      p.cubic({0.0f, 0.32f * H}, {0.1f * L, 0.38f * H}, {0.3f * L, 0.36f * H});
      p.line({0.8f * L, 0.2f * H});
      p.cubic({0.95f * L, 0.16f * H}, {L, 0.08f * H}, {L, 0.0f});
      p.line({0.98f * L, -0.08f * H});
      p.line({0.25f * L, -0.2f * H});
      p.cubic({0.08f * L, -0.22f * H}, {0.0f, -0.15f * H}, {0.0f, 0.0f});
      p.close();
      p.polygon({{0.05f * L, -0.2f * H}, {0.97f * L, -0.12f * H}, {0.95f * L, -0.22f * H},
                 {0.3f * L, -0.4f * H}, {0.08f * L, -0.36f * H}});
      holes.circle({0.33f * L, 0.14f * H}, 0.12f * H);
      holes.circle({0.12f * L, 0.12f * H}, 0.08f * H);
      break;
    }
    case 3: {  // fish: pointed head with a gill cover
      p.move({0.0f, -0.45f * H});
      p.cubic({0.0f, 0.3f * H}, {0.3f * L, 0.55f * H}, {0.6f * L, 0.4f * H});
      p.cubic({0.8f * L, 0.3f * H}, {0.95f * L, 0.1f * H}, {L, -0.02f * H});
      p.line({0.92f * L, -0.15f * H});
      p.cubic({0.6f * L, -0.4f * H}, {0.3f * L, -0.55f * H}, {0.0f, -0.45f * H});
      p.close();
      holes.circle({0.68f * L, 0.12f * H}, 0.13f * H);
      // Operculum edge as a thin crescent.
      holes.move({0.28f * L, 0.3f * H});
      holes.quad({0.4f * L, -0.05f * H}, {0.26f * L, -0.4f * H});
      holes.quad({0.34f * L, -0.05f * H}, {0.28f * L, 0.3f * H});
      holes.close();
      break;
    }
    default: {  // mammal: domed cranium, snout, separate lower jaw
      p.move({0.0f, 0.0f});
      p.cubic({0.0f, 0.45f * H}, {0.2f * L, 0.6f * H}, {0.45f * L, 0.55f * H});
      p.cubic({0.65f * L, 0.5f * H}, {0.8f * L, 0.3f * H}, {L, 0.12f * H});
      p.line({L, -0.08f * H});
      p.cubic({0.8f * L, -0.15f * H}, {0.5f * L, -0.2f * H}, {0.3f * L, -0.25f * H});
      p.cubic({0.15f * L, -0.3f * H}, {0.02f * L, -0.2f * H}, {0.0f, 0.0f});
      p.close();
      p.move({0.15f * L, -0.12f * H});
      p.line({0.2f * L, -0.34f * H});
      p.cubic({0.5f * L, -0.44f * H}, {0.8f * L, -0.3f * H}, {0.97f * L, -0.17f * H});
      p.line({0.95f * L, -0.11f * H});
      p.cubic({0.7f * L, -0.24f * H}, {0.4f * L, -0.28f * H}, {0.25f * L, -0.23f * H});
      p.close();
      holes.circle({0.5f * L, 0.18f * H}, 0.13f * H);
      holes.circle({0.9f * L, 0.06f * H}, 0.05f * H);
      break;
    }
  }
}

// Scapula: a blade from the dorsal border (origin) narrowing to the shoulder joint at (L, 0).
void scapula(PathBuilder& p, PathBuilder& marks, float L, float w) {
  const float h = 0.5f * std::clamp(w, 0.25f * L, 0.9f * L);
  const float rg = 0.3f * h;  // glenoid
  const glm::vec2 g(L - rg, 0.0f);
  p.move({0.0f, -h});
  p.quad({-0.08f * L, 0.0f}, {0.0f, h});
  p.cubic({0.3f * L, 0.95f * h}, {0.6f * L, 0.3f * h}, {g.x - 0.2f * rg, 0.9f * rg});
  p.arc(rg, true, false, {g.x - 0.2f * rg, -0.9f * rg}, g);
  p.cubic({0.6f * L, -0.3f * h}, {0.3f * L, -0.95f * h}, {0.0f, -h});
  p.close();
  // Scapular spine: a ridge along the blade.
  marks.capsule({0.05f * L, 0.1f * h}, {0.8f * L, 0.0f}, 0.06f * h, 0.04f * h);
}

// Pelvis: ilium plate from the sacrum (origin) to the acetabulum at (L, 0), ischium beyond.
void pelvis(PathBuilder& p, PathBuilder& holes, float L, float w) {
  const float h = 0.5f * std::clamp(w, 0.25f * L, 0.9f * L);
  const float ra = 0.32f * h;
  p.move({0.0f, -0.9f * h});
  p.quad({-0.1f * L, 0.0f}, {0.0f, 0.9f * h});
  p.cubic({0.35f * L, 0.9f * h}, {0.7f * L, 0.5f * h}, {L, 1.2f * ra});
  // Ischium: a short wide process beyond the hip joint.
  p.cubic({1.2f * L, 1.5f * ra}, {1.35f * L, 0.5f * ra}, {1.3f * L, -0.6f * ra});
  p.cubic({1.2f * L, -1.6f * ra}, {1.05f * L, -1.4f * ra}, {L, -1.2f * ra});
  p.cubic({0.7f * L, -0.5f * h}, {0.35f * L, -0.9f * h}, {0.0f, -0.9f * h});
  p.close();
  holes.circle({L, 0.0f}, ra);
  holes.circle({1.15f * L, -0.1f * ra}, 0.45f * ra);
}

// The limb a hand/foot bone belongs to decides its shape.
enum class HandShape { kHoof, kPaw, kFlat, kHand, kBirdFoot, kWingHand, kFin };

void hand(PathBuilder& p, PathBuilder& holes, const BoneContext& b, HandShape shape) {
  const float L = b.length;
  const float h = 0.5f * std::clamp(b.width, 0.08f * L, 0.6f * L);
  const glm::vec2 tip(L, 0.0f);
  const glm::vec2 fwd = b.forward_ls;
  switch (shape) {
    case HandShape::kHoof: {
      const float r = 0.6f * h;
      p.capsule({0.0f, 0.0f}, {0.72f * L, 0.0f}, r, 0.8f * r);  // cannon bone
      p.capsule({0.72f * L, 0.0f}, {0.88f * L, 0.0f}, 0.8f * r, 0.75f * r);  // pastern
      // Hoof: a wedge standing on the ground, its toe wall facing forward.
      const glm::vec2 a(0.86f * L, 0.8f * h), c(0.86f * L, -0.8f * h);
      const bool front_is_plus = fwd.y > 0.0f;
      const glm::vec2 front_top = front_is_plus ? a : c, back_top = front_is_plus ? c : a;
      p.polygon({back_top, front_top, tip + fwd * (1.2f * h), tip - fwd * (0.5f * h)});
      break;
    }
    case HandShape::kPaw: {
      const float r = 0.45f * h;
      p.capsule({0.0f, 0.0f}, {0.75f * L, 0.0f}, r, 0.8f * r);  // metapodials
      // Toes: down to the ground, then forward along it, ending in a claw.
      const glm::vec2 knuckle(0.75f * L, 0.0f);
      p.capsule(knuckle, tip, 0.7f * r, 0.6f * r);
      p.capsule(tip, tip + fwd * (0.22f * L), 0.6f * r, 0.25f * r);
      holes.circle(tip, 0.25f * r);
      break;
    }
    case HandShape::kFlat:
    case HandShape::kHand: {
      // Heel/wrist block, metapodials, two phalanges; hands spread three fingers.
      // The block starts at the joint (no gap to the lower limb's knob).
      const float rb = std::min(0.9f * h, 0.2f * L);
      p.circle({0.6f * rb, 0.0f}, rb);
      p.capsule({0.6f * rb, 0.0f}, {0.62f * L, 0.0f}, 0.5f * h, 0.4f * h);
      const int digits = shape == HandShape::kHand ? 3 : 1;
      for (int i = 0; i < digits; ++i) {
        const float spread = (static_cast<float>(i) - 0.5f * (digits - 1)) * 0.18f;
        const glm::vec2 dir(std::cos(spread), std::sin(spread));
        const glm::vec2 base(0.62f * L, 0.0f);
        const glm::vec2 mid = base + dir * (0.2f * L);
        p.capsule(base, mid, 0.38f * h, 0.32f * h);
        p.capsule(mid, base + dir * (0.38f * L), 0.3f * h, 0.18f * h);
      }
      break;
    }
    case HandShape::kBirdFoot: {
      const float r = 0.35f * h;
      p.capsule({0.0f, 0.0f}, tip, r, 0.8f * r);  // tarsometatarsus
      // Three toes forward along the ground (slightly fanned in the side view), one back.
      for (int i = 0; i < 3; ++i) {
        const float a = (static_cast<float>(i) - 1.0f) * 0.12f;
        const glm::vec2 dir(fwd.x * std::cos(a) - fwd.y * std::sin(a),
                            fwd.x * std::sin(a) + fwd.y * std::cos(a));
        const float toe = (0.32f - 0.05f * std::fabs(static_cast<float>(i) - 1.0f)) * L;
        p.capsule(tip, tip + dir * toe, 0.6f * r, 0.2f * r);
      }
      p.capsule(tip, tip - fwd * (0.16f * L), 0.5f * r, 0.2f * r);  // hallux
      break;
    }
    case HandShape::kWingHand: {
      const float r = 0.45f * h;
      p.capsule({0.0f, 0.0f}, tip, r, 0.15f * r);
      p.capsule({0.05f * L, 0.0f}, {0.3f * L, 0.6f * r}, 0.5f * r, 0.2f * r);  // alula
      p.capsule({0.1f * L, 0.0f}, {0.6f * L, -0.5f * r}, 0.4f * r, 0.2f * r);  // digit III
      break;
    }
    case HandShape::kFin: {
      // A fan of rays opening from the base, with a scalloped edge.
      const int rays = 6;
      const float spread = 0.5f;  // radians either side
      p.move({0.0f, 0.25f * h});
      for (int i = 0; i <= rays; ++i) {
        const float a = spread - 2.0f * spread * static_cast<float>(i) / rays;
        const glm::vec2 e(L * std::cos(a), L * std::sin(a));
        if (i == 0) {
          p.line(e);
        } else {
          const float am = a + spread / rays;
          p.quad({0.85f * L * std::cos(am), 0.85f * L * std::sin(am)}, e);
        }
      }
      p.line({0.0f, -0.25f * h});
      p.close();
      for (int i = 1; i < rays; ++i) {
        const float a = spread - 2.0f * spread * static_cast<float>(i) / rays;
        holes.capsule({0.1f * L, 0.0f}, {0.85f * L * std::cos(a), 0.85f * L * std::sin(a)},
                      0.03f * L, 0.01f * L);
      }
      break;
    }
  }
}

// [SECTION] Creature drawing -----------------------------------------------------------------

struct LayerStyle {
  const char* fill;
  const char* stroke;
  const char* hole;
};
constexpr LayerStyle kLayerStyles[kLayerCount] = {
    {"#9c9382", "#4a443a", "#5c554a"},   // far: darker, behind the body
    {"#e2d6ba", "#6b5d45", "#8a7c62"},   // body
    {"#e8dcc0", "#6b5d45", "#8a7c62"},   // near
};

// Drawing order inside a layer: ribs behind girdles behind the spine and skull, limbs on top
// from the girdle outwards.
int kind_order(BoneKind kind) {
  switch (kind) {
    case BoneKind::kRib: return 0;
    case BoneKind::kScapula:
    case BoneKind::kPelvis: return 1;
    case BoneKind::kNeckVertebra:
    case BoneKind::kBackVertebra:
    case BoneKind::kTailVertebra:
    case BoneKind::kRoot: return 2;
    case BoneKind::kSkull: return 3;
    case BoneKind::kUpperLimb: return 4;
    case BoneKind::kLowerLimb: return 5;
    case BoneKind::kHand: return 6;
  }
  return 7;
}

bool finite(const Mat2x3& m) {
  for (float v : m.m) {
    if (!std::isfinite(v)) return false;
  }
  return true;
}

int auto_skull_variant(const Creature& c) {
  int wings = 0, legs = 0, fins = 0;
  for (const Limb& l : c.limbs) {
    wings += l.kind == LimbKind::kWing;
    legs += l.kind == LimbKind::kLeg;
    fins += l.kind == LimbKind::kFin;
  }
  if (wings > 0) return 1;
  if (legs == 0 && fins > 0) return 3;
  if (c.skull >= 0) {
    const float L = c.skeleton.length(c.skull), w = c.skeleton.width(c.skull);
    if (w > 0.0f && L > 2.6f * w) return 2;
  }
  return 0;
}

// `dir_ms`: the hand/foot bone's unit direction in model space.
HandShape hand_shape(const Creature& c, const Limb& limb, bool winged, const Skeleton& s,
                     glm::vec2 dir_ms) {
  switch (limb.kind) {
    case LimbKind::kWing: return HandShape::kWingHand;
    case LimbKind::kFin: return HandShape::kFin;
    case LimbKind::kArm: return HandShape::kHand;
    case LimbKind::kLeg: break;
  }
  if (winged) return HandShape::kBirdFoot;
  if (c.contact == ContactMode::kFlat) return HandShape::kFlat;
  // Tip contact: ungulates stand on long, steep metapodials (cannon bones) ending in a hoof;
  // a foot that lies nearly flat (kangaroo) reads as a flat foot; the rest as a paw.
  const float lower = s.length(limb.bones[1]);
  const float steep = std::fabs(dir_ms.y);
  if (steep < 0.5f) return HandShape::kFlat;
  return steep > 0.7f && s.length(limb.bones[2]) >= 0.45f * lower ? HandShape::kHoof
                                                                   : HandShape::kPaw;
}

struct Drawing {
  std::string content;  // a <g> in model coordinates, y flipped
  float vx = 0.0f, vy = 0.0f, vw = 1.0f, vh = 1.0f;  // viewBox
};

Drawing draw_creature(const Creature& c, const SvgOptions& options) {
  const Skeleton& s = c.skeleton;
  const int n = s.bone_count();
  const std::vector<BoneLocal>& locals =
      c.rest_pose.locals.size() == static_cast<size_t>(n) ? c.rest_pose.locals : s.rest_locals();
  const std::vector<Mat2x3> m = model_matrices(s, locals);

  // Spine bones on the chain from the head end to the root point headward (+x to the head).
  std::vector<char> headward(static_cast<size_t>(n), 0);
  int head_end = !c.neck.empty() ? c.neck.front() : !c.back.empty() ? c.back.front() : -1;
  if (c.skull >= 0 && c.skull < n) head_end = c.skull;
  for (int b = head_end; b >= 0 && b < n; b = s.parent(b)) headward[static_cast<size_t>(b)] = 1;

  std::vector<int> limb_of(static_cast<size_t>(n), -1);
  bool winged = false;
  for (size_t i = 0; i < c.limbs.size(); ++i) {
    const Limb& l = c.limbs[i];
    winged |= l.kind == LimbKind::kWing;
    for (int b : l.bones) {
      if (b >= 0 && b < n) limb_of[static_cast<size_t>(b)] = static_cast<int>(i);
    }
  }
  const int skull_variant =
      options.skull_variant >= 0 ? options.skull_variant % 4 : auto_skull_variant(c);

  // Bone order: by layer, then by kind, then by index.
  std::vector<int> order;
  for (int i = 0; i < n; ++i) {
    if (s.length(i) > 0.0f && std::isfinite(s.length(i)) && std::isfinite(s.width(i)) &&
        finite(m[static_cast<size_t>(i)])) {
      order.push_back(i);
    }
  }
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    const int la = static_cast<int>(s.layer(a)), lb = static_cast<int>(s.layer(b));
    if (la != lb) return la < lb;
    return kind_order(s.kind(a)) < kind_order(s.kind(b));
  });

  Bounds bounds;
  float max_extent = 0.0f;
  std::string layers[kLayerCount];
  for (int i : order) {
    const Mat2x3& mi = m[static_cast<size_t>(i)];
    const float L = s.length(i);
    const float w = s.width(i) > 0.0f ? s.width(i) : 0.15f * L;
    BoneContext ctx;
    ctx.length = L;
    ctx.width = w;
    ctx.headward = headward[static_cast<size_t>(i)] != 0;
    const glm::vec2 fx(mi.m[0], mi.m[2]), uy(mi.m[1], mi.m[3]);
    ctx.forward_ls = glm::length(fx) > 0.0f ? glm::normalize(fx) : glm::vec2(1.0f, 0.0f);
    ctx.up_ls = glm::length(uy) > 0.0f ? glm::normalize(uy) : glm::vec2(0.0f, 1.0f);

    const bool vertebra_bone = s.kind(i) == BoneKind::kNeckVertebra ||
                               s.kind(i) == BoneKind::kBackVertebra ||
                               s.kind(i) == BoneKind::kTailVertebra;
    const bool flip = vertebra_bone && !ctx.headward;
    PathBuilder shape(flip, L), holes(flip, L);
    switch (s.kind(i)) {
      case BoneKind::kRoot: break;
      case BoneKind::kSkull: skull(shape, holes, L, w, skull_variant); break;
      case BoneKind::kNeckVertebra: vertebra(shape, L, w, 0.35f * w); break;
      case BoneKind::kBackVertebra: vertebra(shape, L, w, 1.1f * w); break;
      case BoneKind::kTailVertebra: vertebra(shape, L, w, 0.25f * w); break;
      case BoneKind::kRib: {
        PathBuilder r;  // ribs bulge towards the tail (model -x)
        rib(r, L, w, ctx.forward_ls.y > 0.0f ? -1.0f : 1.0f);
        shape = r;
        break;
      }
      case BoneKind::kScapula: {
        PathBuilder sp, marks;
        scapula(sp, marks, L, w);
        shape = sp;
        holes = marks;
        break;
      }
      case BoneKind::kPelvis: {
        PathBuilder pv, hl;
        pelvis(pv, hl, L, w);
        shape = pv;
        holes = hl;
        break;
      }
      case BoneKind::kUpperLimb:
      case BoneKind::kLowerLimb: {
        PathBuilder lb;
        const int li = limb_of[static_cast<size_t>(i)];
        const bool fin = li >= 0 && c.limbs[static_cast<size_t>(li)].kind == LimbKind::kFin;
        long_bone(lb, L, fin ? 0.6f * w : w);
        shape = lb;
        break;
      }
      case BoneKind::kHand: {
        PathBuilder hb, hh;
        const int li = limb_of[static_cast<size_t>(i)];
        const HandShape hs = li >= 0 ? hand_shape(c, c.limbs[static_cast<size_t>(li)], winged, s,
                                                          glm::normalize(glm::vec2(mi.m[0], mi.m[1])))
                                     : HandShape::kFlat;
        hand(hb, hh, ctx, hs);
        shape = hb;
        holes = hh;
        break;
      }
    }
    if (shape.empty()) continue;
    for (glm::vec2 p : shape.points()) bounds.add(mi.apply(p));
    max_extent = std::max(max_extent, L);

    std::string& out = layers[static_cast<int>(s.layer(i))];
    out += "<g transform=\"matrix(";
    for (int k = 0; k < 6; ++k) {
      if (k) out += ' ';
      append_num(out, mi.m[k]);
    }
    out += ")\" data-bone=\"" + xml_escape(s.name(i)) + "\"><path d=\"" + shape.data() + "\"/>";
    if (!holes.empty()) {
      out += "<path fill=\"" + std::string(kLayerStyles[static_cast<int>(s.layer(i))].hole) +
             "\" d=\"" + holes.data() + "\"/>";
    }
    out += "</g>\n";
  }

  if (bounds.empty()) bounds.add({0.0f, 0.0f}), bounds.add({1.0f, 1.0f});
  const float extent = std::max({bounds.hi.x - bounds.lo.x, bounds.hi.y - bounds.lo.y, 1e-6f});
  const float margin = std::max(0.0f, options.margin) * extent;
  const float stroke = 0.0025f * extent;

  Drawing d;
  std::string& g = d.content;
  g += "<g transform=\"scale(1 -1)\" stroke-width=\"" + num(stroke) +
       "\" stroke-linejoin=\"round\">\n";
  if (options.ground) {
    const float x0 = bounds.lo.x - margin, x1 = bounds.hi.x + margin;
    const float depth = 0.6f * margin;
    g += "<rect x=\"" + num(x0) + "\" y=\"" + num(-depth) + "\" width=\"" + num(x1 - x0) +
         "\" height=\"" + num(depth) + "\" fill=\"#d8d2c4\" stroke=\"none\"/>\n";
    g += "<line x1=\"" + num(x0) + "\" y1=\"0\" x2=\"" + num(x1) + "\" y2=\"0\" stroke=\"#7a705e\" "
         "stroke-width=\"" + num(2.0f * stroke) + "\"/>\n";
    bounds.add({x0, -depth});
    bounds.add({x1, 0.0f});
  }
  for (int l = 0; l < kLayerCount; ++l) {
    if (layers[l].empty()) continue;
    g += "<g class=\"" + std::string(layer_name(static_cast<Layer>(l))) + "\" fill=\"" +
         kLayerStyles[l].fill + "\" stroke=\"" + kLayerStyles[l].stroke + "\">\n" + layers[l] +
         "</g>\n";
  }
  g += "</g>\n";
  d.vx = bounds.lo.x - margin;
  d.vy = -(bounds.hi.y + margin);
  d.vw = bounds.hi.x - bounds.lo.x + 2.0f * margin;
  d.vh = bounds.hi.y - bounds.lo.y + 2.0f * margin;
  if (options.ground) d.vh -= margin;  // the soil strip already adds space below y = 0
  return d;
}

std::string view_box(const Drawing& d) {
  return num(d.vx) + " " + num(d.vy) + " " + num(d.vw) + " " + num(d.vh);
}

}  // namespace

// [SECTION] Documents ------------------------------------------------------------------------

std::string xml_escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char ch : text) {
    switch (ch) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default:
        // Control characters other than tab/newline are not allowed in XML 1.0.
        if (static_cast<unsigned char>(ch) < 0x20 && ch != '\t' && ch != '\n' && ch != '\r') {
          out += '?';
        } else {
          out += ch;
        }
    }
  }
  return out;
}

std::string creature_svg(const Creature& creature, const SvgOptions& options) {
  const Drawing d = draw_creature(creature, options);
  const int width = std::max(16, options.width_px);
  const int height = std::max(16, static_cast<int>(std::lround(width * d.vh / d.vw)));
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(width) +
         "\" height=\"" + std::to_string(height) + "\" viewBox=\"" + view_box(d) + "\">\n";
  if (options.title) out += "<title>" + xml_escape(creature.name) + "</title>\n";
  out += "<rect x=\"" + num(d.vx) + "\" y=\"" + num(d.vy) + "\" width=\"" + num(d.vw) +
         "\" height=\"" + num(d.vh) + "\" fill=\"#ffffff\"/>\n";
  out += d.content;
  out += "</svg>\n";
  return out;
}

std::string sheet_svg(const std::vector<std::pair<std::string, Creature>>& creatures,
                      int columns, const std::vector<int>& skull_variants,
                      const SvgOptions& options) {
  columns = std::max(1, columns);
  const int count = static_cast<int>(creatures.size());
  const int rows = std::max(1, (count + columns - 1) / columns);
  const int cell_w = 240, cell_h = 170, label_h = 36, pad = 8;
  const int width = columns * cell_w, height = rows * (cell_h + label_h);
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(width) +
         "\" height=\"" + std::to_string(height) + "\" viewBox=\"0 0 " + std::to_string(width) +
         " " + std::to_string(height) + "\">\n<rect width=\"" + std::to_string(width) +
         "\" height=\"" + std::to_string(height) + "\" fill=\"#ffffff\"/>\n";
  for (int i = 0; i < count; ++i) {
    SvgOptions o = options;
    if (skull_variants.size() == creatures.size()) o.skull_variant = skull_variants[static_cast<size_t>(i)];
    const Drawing d = draw_creature(creatures[static_cast<size_t>(i)].second, o);
    const int x = (i % columns) * cell_w, y = (i / columns) * (cell_h + label_h);
    out += "<svg x=\"" + std::to_string(x + pad) + "\" y=\"" + std::to_string(y + pad) +
           "\" width=\"" + std::to_string(cell_w - 2 * pad) + "\" height=\"" +
           std::to_string(cell_h - pad) + "\" viewBox=\"" + view_box(d) +
           "\" preserveAspectRatio=\"xMidYMax meet\">\n" + d.content + "</svg>\n";
    // Label: "english (German)" on two lines, the part in parentheses smaller.
    const std::string& label = creatures[static_cast<size_t>(i)].first;
    const size_t paren = label.find(" (");
    const std::string line1 = label.substr(0, paren);
    const std::string line2 = paren == std::string::npos ? std::string() : label.substr(paren + 1);
    out += "<text x=\"" + std::to_string(x + cell_w / 2) + "\" y=\"" +
           std::to_string(y + cell_h + 14) +
           "\" text-anchor=\"middle\" font-family=\"sans-serif\" font-size=\"15\" "
           "fill=\"#333333\">" + xml_escape(line1);
    if (!line2.empty()) {
      out += "<tspan x=\"" + std::to_string(x + cell_w / 2) +
             "\" dy=\"16\" font-size=\"12\" fill=\"#666666\">" + xml_escape(line2) + "</tspan>";
    }
    out += "</text>\n";
  }
  out += "</svg>\n";
  return out;
}

}  // namespace ossa
