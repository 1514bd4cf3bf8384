#include "ossa/gen/svg_bone_shapes.h"

#include <algorithm>
#include <cmath>

namespace ossa::svg {

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

}  // namespace ossa::svg
