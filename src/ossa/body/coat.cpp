#include "ossa/body/coat.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace ossa {

namespace {

// GLSL's smoothstep, for the CPU twin of body.frag.
float smoothstep(float e0, float e1, float x) {
  const float t = std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

uint32_t cell_hash(int x, int y) {
  return coat_hash(static_cast<uint32_t>(x) * 0x9e3779b1u ^ coat_hash(static_cast<uint32_t>(y) + 0x85ebca6bu));
}

float unit(uint32_t h) { return static_cast<float>(h >> 8) * (1.0f / 16777216.0f); }

}  // namespace

uint32_t coat_hash(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

float coat_value_noise(glm::vec2 p) {
  const float fx = std::floor(p.x), fy = std::floor(p.y);
  const int ix = static_cast<int>(fx), iy = static_cast<int>(fy);
  const float tx = p.x - fx, ty = p.y - fy;
  const float ux = tx * tx * (3.0f - 2.0f * tx), uy = ty * ty * (3.0f - 2.0f * ty);
  const float a = unit(cell_hash(ix, iy)), b = unit(cell_hash(ix + 1, iy));
  const float c = unit(cell_hash(ix, iy + 1)), d = unit(cell_hash(ix + 1, iy + 1));
  return (a + (b - a) * ux) + ((c + (d - c) * ux) - (a + (b - a) * ux)) * uy;
}

Worley coat_worley(glm::vec2 p) {
  const float fx = std::floor(p.x), fy = std::floor(p.y);
  const int ix = static_cast<int>(fx), iy = static_cast<int>(fy);
  Worley w;
  w.f1 = 8.0f;
  w.f2 = 8.0f;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      const uint32_t h = cell_hash(ix + dx, iy + dy);
      const glm::vec2 point(fx + static_cast<float>(dx) + 0.1f + 0.8f * unit(h),
                            fy + static_cast<float>(dy) + 0.1f + 0.8f * unit(coat_hash(h)));
      const float d = glm::length(p - point);
      if (d < w.f1) {
        w.f2 = w.f1;
        w.f1 = d;
        w.cell = h;
      } else if (d < w.f2) {
        w.f2 = d;
      }
    }
  }
  return w;
}

float coat_pattern(CoatPattern pattern, glm::vec2 p, float aa) {
  aa = std::max(aa, 1e-4f);
  switch (pattern) {
    case CoatPattern::kNone: return 0.0f;
    case CoatPattern::kStripes: {
      const float x = p.x + 0.2f * p.y + 0.9f * (coat_value_noise(0.5f * p) - 0.5f);
      const float d = std::fabs(x - std::floor(x) - 0.5f);
      const float w = 0.16f + 0.1f * coat_value_noise(p + glm::vec2(17.0f, 5.0f));
      return smoothstep(0.5f - w - aa, 0.5f - w + aa, d);
    }
    case CoatPattern::kSpots: {
      const Worley w = coat_worley(p);
      const float r = 0.16f + 0.14f * unit(coat_hash(w.cell + 1u));
      return 1.0f - smoothstep(r - aa, r + aa, w.f1);
    }
    case CoatPattern::kRosettes: {
      const Worley w = coat_worley(p);
      const float r_in = 0.17f + 0.06f * unit(coat_hash(w.cell + 2u)), r_out = r_in + 0.13f;
      const float ring = smoothstep(r_in - aa, r_in + aa, w.f1) * (1.0f - smoothstep(r_out - aa, r_out + aa, w.f1));
      return ring * smoothstep(0.3f, 0.4f, coat_value_noise(3.3f * p));
    }
    case CoatPattern::kDapples: {
      const float n = 0.6f * coat_value_noise(p) + 0.4f * coat_value_noise(2.3f * p + glm::vec2(3.1f, 7.7f));
      return 0.85f * smoothstep(0.52f - aa, 0.6f + aa, n);
    }
    case CoatPattern::kPatches: {
      const Worley w = coat_worley(p);
      return smoothstep(0.07f - aa, 0.07f + aa, w.f2 - w.f1);
    }
  }
  return 0.0f;
}

glm::vec3 countershade(const Look& look, float v) {
  const glm::vec3 back = look.base * 0.78f;
  if (v <= 0.45f) return glm::mix(back, look.base, smoothstep(0.0f, 0.45f, v));
  if (v <= 1.0f) return glm::mix(look.base, look.belly, smoothstep(0.5f, 0.95f, v));
  return glm::mix(look.belly, look.base * 0.92f, smoothstep(1.0f, 1.4f, v));
}

glm::vec3 outline_colour(const Look& look) { return look.base * 0.3f + glm::vec3(0.02f); }

std::array<uint8_t, 4> to_rgba8(glm::vec4 c) {
  std::array<uint8_t, 4> out{};
  for (int i = 0; i < 4; ++i) {
    const float x = std::isfinite(c[i]) ? std::clamp(c[i], 0.0f, 1.0f) : 0.0f;
    out[static_cast<size_t>(i)] = static_cast<uint8_t>(std::lround(x * 255.0f));
  }
  return out;
}

}  // namespace ossa
