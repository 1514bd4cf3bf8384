#include "ossa/render/box_look.h"

#include <algorithm>
#include <cmath>

#include "ossa/level/level.h"

namespace ossa {

namespace {

constexpr float kTouch = 1e-4f;  // metres: a box this close over an edge covers it

// Texture coordinate of world position `x` on a grid of side t, with the grid cell of `x0`
// moved to 0 (keeps floats small far from the origin).
struct GridU {
  double base;
  double t;
  float operator()(float x) const { return static_cast<float>(static_cast<double>(x) / t - base); }
};
GridU grid_from(float x0, float t) { return {std::floor(static_cast<double>(x0) / t), static_cast<double>(t)}; }

}  // namespace

int look_tile(const LevelLook& look, LookPart part) {
  switch (part) {
    case LookPart::kFill: return look.fill;
    case LookPart::kLeft: return look.left;
    case LookPart::kRight: return look.right;
    case LookPart::kTop: return look.top;
    case LookPart::kTopLeft: return look.top_left;
    case LookPart::kTopRight: return look.top_right;
    case LookPart::kCount: break;
  }
  return -1;
}

size_t BoxLookGeometry::quad_count() const {
  size_t n = 0;
  for (const auto& p : parts) n += p.size();
  return n;
}

std::vector<glm::vec2> uncovered(float lo, float hi, std::vector<glm::vec2> covers, float min_length) {
  std::sort(covers.begin(), covers.end(), [](glm::vec2 a, glm::vec2 b) { return a.x < b.x; });
  std::vector<glm::vec2> out;
  float at = lo;
  for (const glm::vec2 c : covers) {
    if (c.y <= at) continue;
    if (c.x >= hi) break;
    if (c.x - at >= min_length) out.push_back({at, std::min(c.x, hi)});
    at = std::max(at, c.y);
    if (at >= hi) break;
  }
  if (hi - at >= min_length) out.push_back({at, hi});
  return out;
}

BoxLookGeometry build_box_look(const Level& level, const LevelLook& look) {
  BoxLookGeometry g;
  const float t = look.tile_m;
  if (!(t > 0.0f)) return g;
  std::vector<int> near;
  std::vector<glm::vec2> covers;
  auto covered_along = [&](const Box& strip, bool along_x) {
    near.clear();
    covers.clear();
    level.overlapping(strip, near);
    for (int i : near) {
      const Box& o = level.box(i);
      covers.push_back(along_x ? glm::vec2(o.min_ws.x, o.max_ws.x) : glm::vec2(o.min_ws.y, o.max_ws.y));
    }
    return along_x ? uncovered(strip.min_ws.x, strip.max_ws.x, covers) : uncovered(strip.min_ws.y, strip.max_ws.y, covers);
  };
  auto add = [&](LookPart part, const Box& rect, glm::vec2 uv_min, glm::vec2 uv_max) {
    if (look_tile(look, part) < 0 || !rect.is_valid()) return;
    g.parts[static_cast<size_t>(part)].push_back({rect, uv_min, uv_max});
  };
  for (const Box& b : level.colliders()) {
    const float w = std::min(t, b.width()), h = std::min(t, b.height());
    const GridU u = grid_from(b.min_ws.x, t), v = grid_from(b.min_ws.y, t);
    add(LookPart::kFill, b, {u(b.min_ws.x), v(b.min_ws.y)}, {u(b.max_ws.x), v(b.max_ws.y)});

    // Sides: the stretches no box covers just outside them.
    const auto left = look.left >= 0 ? covered_along(Box{{b.min_ws.x - kTouch, b.min_ws.y}, {b.min_ws.x, b.max_ws.y}}, false)
                                     : std::vector<glm::vec2>{};
    const auto right = look.right >= 0 ? covered_along(Box{{b.max_ws.x, b.min_ws.y}, {b.max_ws.x + kTouch, b.max_ws.y}}, false)
                                       : std::vector<glm::vec2>{};
    for (const glm::vec2 s : left) {
      add(LookPart::kLeft, Box{{b.min_ws.x, s.x}, {b.min_ws.x + w, s.y}}, {0.0f, v(s.x)}, {w / t, v(s.y)});
    }
    for (const glm::vec2 s : right) {
      add(LookPart::kRight, Box{{b.max_ws.x - w, s.x}, {b.max_ws.x, s.y}}, {1.0f - w / t, v(s.x)}, {1.0f, v(s.y)});
    }

    // Top: the stretches no box covers just above it; corners where they meet a bare side.
    const auto tops = covered_along(Box{{b.min_ws.x, b.max_ws.y}, {b.max_ws.x, b.max_ws.y + kTouch}}, true);
    const float top = b.max_ws.y;
    const float v0 = 1.0f - h / t;
    for (const glm::vec2 s : tops) add(LookPart::kTop, Box{{s.x, top - h}, {s.y, top}}, {u(s.x), v0}, {u(s.y), 1.0f});
    const auto side_bare_at_top = [&](const std::vector<glm::vec2>& side) {
      return !side.empty() && side.back().y >= top - kTouch;
    };
    // Without side tiles a corner still ends the grass where the side is bare.
    const auto bare = [&](bool left_side) {
      if (left_side ? look.left >= 0 : look.right >= 0) return side_bare_at_top(left_side ? left : right);
      const float x = left_side ? b.min_ws.x : b.max_ws.x;
      return side_bare_at_top(covered_along(Box{{x - (left_side ? kTouch : 0.0f), top - h}, {x + (left_side ? 0.0f : kTouch), top}}, false));
    };
    if (!tops.empty() && tops.front().x <= b.min_ws.x + kTouch && bare(true)) {
      add(LookPart::kTopLeft, Box{{b.min_ws.x, top - h}, {b.min_ws.x + w, top}}, {0.0f, v0}, {w / t, 1.0f});
    }
    if (!tops.empty() && tops.back().y >= b.max_ws.x - kTouch && bare(false)) {
      add(LookPart::kTopRight, Box{{b.max_ws.x - w, top - h}, {b.max_ws.x, top}}, {1.0f - w / t, v0}, {1.0f, 1.0f});
    }
  }
  return g;
}

}  // namespace ossa
