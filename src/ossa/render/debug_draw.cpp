#include "ossa/render/debug_draw.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include "ossa/level/level.h"

namespace ossa {

std::span<const VertexAttrib> DebugVertex::layout() {
  static const std::array<VertexAttrib, 2> kLayout{{
      {0, 2, GL_FLOAT, false, false, offsetof(DebugVertex, position_ws)},
      {1, 4, GL_UNSIGNED_BYTE, true, false, offsetof(DebugVertex, rgba)},
  }};
  return kLayout;
}

uint32_t pack_rgba(glm::vec4 c) {
  auto byte = [](float v) {
    return static_cast<uint32_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
  };
  return byte(c.r) | (byte(c.g) << 8) | (byte(c.b) << 16) | (byte(c.a) << 24);
}

void DebugDraw::clear() {
  lines_.clear();
  triangles_.clear();
}

void DebugDraw::add_line(glm::vec2 a, glm::vec2 b, glm::vec4 colour) {
  const uint32_t c = pack_rgba(colour);
  lines_.push_back({a, c});
  lines_.push_back({b, c});
}

void DebugDraw::add_triangle(glm::vec2 a, glm::vec2 b, glm::vec2 c, glm::vec4 colour) {
  const uint32_t k = pack_rgba(colour);
  triangles_.push_back({a, k});
  triangles_.push_back({b, k});
  triangles_.push_back({c, k});
}

void DebugDraw::add_box(const Box& box, glm::vec4 colour, bool filled) {
  const glm::vec2 a = box.min_ws, c = box.max_ws, b{c.x, a.y}, d{a.x, c.y};
  if (filled) {
    add_triangle(a, b, c, colour);
    add_triangle(a, c, d, colour);
  } else {
    add_line(a, b, colour);
    add_line(b, c, colour);
    add_line(c, d, colour);
    add_line(d, a, colour);
  }
}

void DebugDraw::add_polyline(std::span<const glm::vec2> points, glm::vec4 colour) {
  for (size_t i = 1; i < points.size(); ++i) add_line(points[i - 1], points[i], colour);
}

void DebugDraw::add_cross(glm::vec2 p, float size, glm::vec4 colour) {
  add_line(p + glm::vec2(-size, -size), p + glm::vec2(size, size), colour);
  add_line(p + glm::vec2(-size, size), p + glm::vec2(size, -size), colour);
}

void DebugDraw::add_level(const Level& level, glm::vec4 fill, glm::vec4 outline) {
  for (const Box& box : level.colliders()) {
    add_box(box, fill, true);
    add_box(box, outline, false);
  }
}

int DebugDraw::draw() {
  int calls = 0;
  if (!triangles_.empty()) {
    if (!triangle_va_) triangle_va_ = std::make_unique<VertexArray<DebugVertex>>();
    triangle_va_->upload(triangles_, {}, GL_STREAM_DRAW);
    triangle_va_->draw(GL_TRIANGLES);
    ++calls;
  }
  if (!lines_.empty()) {
    if (!line_va_) line_va_ = std::make_unique<VertexArray<DebugVertex>>();
    line_va_->upload(lines_, {}, GL_STREAM_DRAW);
    line_va_->draw(GL_LINES);
    ++calls;
  }
  return calls;
}

}  // namespace ossa
