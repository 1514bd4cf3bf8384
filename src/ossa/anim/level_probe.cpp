#include "ossa/anim/level_probe.h"

#include <algorithm>
#include <cmath>

#include "ossa/anim/ground_profile.h"

namespace ossa::anim {

namespace {
// The colliders shrunk by a hair less than the 1 mm the tests and the sweep allow a limb into
// a box: a pose the clearances settle exactly at the shrunk surface (a bisection's last step)
// stays within the limit after rounding (the eared seal's flipper read 1.0004 mm).
constexpr float kShrink = 0.99e-3f;
}  // namespace

std::optional<GroundHit> ground_below(const Level& level, float x0, float x1, float from_y, float max_drop) {
  return level.ground_height_below(std::min(x0, x1), std::max(x0, x1), from_y, std::max(max_drop, 0.0f));
}

std::optional<float> standing_ground(const Level& level, float x, float lo, float hi, float from_y, float max_drop, float climb) {
  const auto span = ground_below(level, lo, hi, from_y, max_drop);
  if (!span || !(climb < INFINITY)) return span ? std::optional<float>(span->height_ws) : std::nullopt;
  const auto under = ground_below(level, x, x, from_y, max_drop);
  if (!under) return span->height_ws;
  // Walked from the ground under x riser by riser (a flight of steps lower than `climb` is
  // ground, a wall is not), in columns of at most kStandingColumns over the span. (A reset's
  // question: the profile is built for it.)
  constexpr float kStandingColumns = 1024.0f, kStandingStepMin = 0.005f;
  const float step = std::max((hi - lo) / kStandingColumns, kStandingStepMin);
  thread_local GroundProfile profile;
  profile.build(level, lo - step, hi + 2.0f * step, from_y, std::max(max_drop, 0.0f), step);
  const float top = profile.climbable_top(x, lo, hi, hi, lo, under->height_ws, climb);
  return std::isnan(top) ? span->height_ws : std::min(top, span->height_ws);
}

namespace {

// Pushes the body towards `dir` past every box its standing region overlaps until it overlaps
// none; nullopt beyond `reach` or after too many boxes.
std::optional<float> push_clear(const Level& level, float x, float back, float front, float top, float from_y,
                                float max_drop, float climb, float reach, int dir, std::vector<int>& hits) {
  constexpr int kMaxPushes = 64;
  const float start = x;
  for (int i = 0; i < kMaxPushes && std::abs(x - start) <= reach; ++i) {
    const float lo = x + back, hi = x + front;
    const auto ground = standing_ground(level, x, lo, hi, from_y, max_drop, climb);
    if (!ground) return std::nullopt;  // off the level's edge: no place to stand this way
    const float base = *ground;
    hits.clear();
    level.overlapping(Box{{lo, base + 1e-3f}, {hi, base + std::max(top, 2e-3f)}}, hits);
    if (hits.empty()) return x;
    float shift = 0.0f;
    for (int h : hits) {
      const Box& b = level.box(h);
      shift = std::max(shift, dir > 0 ? b.max_ws.x - lo : hi - b.min_ws.x);
    }
    x += static_cast<float>(dir) * (shift + 1e-3f);
  }
  return std::nullopt;
}

}  // namespace

float clear_standing_x(const Level& level, float x, float back, float front, float top, float from_y, float max_drop,
                       float climb, float reach, std::vector<int>& hits) {
  const auto right = push_clear(level, x, back, front, top, from_y, max_drop, climb, reach, 1, hits);
  const auto left = push_clear(level, x, back, front, top, from_y, max_drop, climb, reach, -1, hits);
  if (right && left) return *right - x <= x - *left ? *right : *left;
  return right ? *right : left ? *left : x;
}

bool polyline_hits_level(const Level& level, const glm::vec2* p, int n, std::vector<int>& hits, float above_y, float top_over) {
  glm::vec2 lo = p[0], hi = p[0];
  for (int i = 1; i < n; ++i) {
    lo = glm::min(lo, p[i]);
    hi = glm::max(hi, p[i]);
  }
  hits.clear();
  level.overlapping(Box{lo, hi}, hits);
  for (int h : hits) {
    const Box& box = level.box(h);
    if (box.min_ws.y < above_y || box.top() <= top_over) continue;
    for (int i = 0; i + 1 < n; ++i) {
      const glm::vec2 a = p[i], b = p[i + 1];
      float t0 = 0.0f, t1 = 1.0f;
      bool inside = true;
      for (int axis = 0; axis < 2 && inside; ++axis) {
        const float lo_a = box.min_ws[axis] + kShrink, hi_a = box.max_ws[axis] - kShrink;
        const float d = b[axis] - a[axis];
        if (std::fabs(d) < 1e-9f) {
          inside = a[axis] > lo_a && a[axis] < hi_a;
        } else {
          float u0 = (lo_a - a[axis]) / d, u1 = (hi_a - a[axis]) / d;
          if (u0 > u1) std::swap(u0, u1);
          t0 = std::max(t0, u0);
          t1 = std::min(t1, u1);
          inside = t0 < t1;
        }
      }
      if (inside) return true;
    }
  }
  return false;
}

float keep_out_height(const Level& level, float x, float half, float keep, float fade, float from_y, float max_drop,
                      std::vector<int>& hits) {
  // The highest ground over the whole window first: when its box lies within `half`, it
  // decides alone (every other box's claim is lower), which is flat ground's case.
  const auto highest = ground_below(level, x - 2.0f * half, x + 2.0f * half, from_y, max_drop);
  if (!highest) return -1e30f;
  const Box& top_box = level.box(highest->index);
  if (std::max({0.0f, top_box.min_ws.x - x, x - top_box.max_ws.x}) <= half) return highest->height_ws + keep;
  hits.clear();
  level.overlapping(Box{{x - 2.0f * half, from_y - max_drop - kGroundEpsilon}, {x + 2.0f * half, from_y + kGroundEpsilon}}, hits);
  float need = -1e30f;
  for (int h : hits) {
    const Box& box = level.box(h);
    const float top = box.top();
    if (top > from_y + kGroundEpsilon || top < from_y - max_drop) continue;  // a wall above, or too deep
    const float dist = std::max({0.0f, box.min_ws.x - x, x - box.max_ws.x});
    const float t = std::clamp((dist - half) / std::max(half, 1e-6f), 0.0f, 1.0f);
    need = std::max(need, top + keep - t * t * (3.0f - 2.0f * t) * (keep + fade));
  }
  return need;
}

bool segment_x_within(glm::vec2 a, glm::vec2 b, float y0, float y1, float* x0, float* x1) {
  float t0 = 0.0f, t1 = 1.0f;
  if (a.y != b.y) {
    const float u = (y0 - a.y) / (b.y - a.y), v = (y1 - a.y) / (b.y - a.y);
    t0 = std::max(t0, std::min(u, v));
    t1 = std::min(t1, std::max(u, v));
  } else if (!(a.y > y0 && a.y < y1)) {
    return false;
  }
  if (!(t0 < t1)) return false;
  const float xa = a.x + (b.x - a.x) * t0, xb = a.x + (b.x - a.x) * t1;
  *x0 = std::min(xa, xb);
  *x1 = std::max(xa, xb);
  return true;
}

float raise_to_clear(glm::vec2 a, glm::vec2 b, const Level& level, std::vector<int>& hits, float max_top) {
  // Over the part of the box's width the segment spans, its lowest point to the box's top.
  hits.clear();
  level.overlapping(Box{glm::min(a, b) - glm::vec2(1e-4f), glm::max(a, b) + glm::vec2(1e-4f)}, hits);
  float need = 0.0f;
  for (int h : hits) {
    const Box& box = level.box(h);
    if (box.top() > max_top) continue;
    const float lo = std::max(std::min(a.x, b.x), box.min_ws.x), hi = std::min(std::max(a.x, b.x), box.max_ws.x);
    if (lo > hi) continue;
    auto y_at = [&](float x) { return std::fabs(b.x - a.x) < 1e-6f ? std::min(a.y, b.y) : a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x); };
    const float y0 = y_at(lo), y1 = y_at(hi);
    if (std::max(y0, y1) <= box.min_ws.y) continue;  // passes under it
    need = std::max(need, box.top() - std::min(y0, y1));
  }
  return need;
}

Clearance clearance_in(const Box& region, float base, const Level& level, std::vector<int>& hits) {
  Clearance c;
  c.base = base;
  c.top = -1e30f;
  hits.clear();
  level.overlapping(region, hits);
  for (int h : hits) {
    const float top = level.box(h).top();
    if (top > base + 0.5e-3f) c.top = std::max(c.top, top);
  }
  return c;
}

}  // namespace ossa::anim
