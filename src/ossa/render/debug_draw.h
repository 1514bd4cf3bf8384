#pragma once
// DebugDraw — flat-coloured lines and triangles collected on the CPU during a frame and drawn
// by the Debug program in two draw calls (Renderer::draw_debug): colliders, splines, targets.
// World space, metres.

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "ossa/level/box.h"
#include "ossa/render/vertex_array.h"

namespace ossa {

class Level;

struct DebugVertex {
  glm::vec2 position_ws{0.0f};
  uint32_t rgba = 0xffffffffu;  // R in the lowest byte (memory order R, G, B, A)
  static std::span<const VertexAttrib> layout();
};

// Packs a colour with components in [0, 1] (clamped) into DebugVertex::rgba.
uint32_t pack_rgba(glm::vec4 colour);

class DebugDraw {
 public:
  void clear();
  void add_line(glm::vec2 a_ws, glm::vec2 b_ws, glm::vec4 colour);
  void add_triangle(glm::vec2 a_ws, glm::vec2 b_ws, glm::vec2 c_ws, glm::vec4 colour);
  // Outline (4 lines) or filled (2 triangles).
  void add_box(const Box& box, glm::vec4 colour, bool filled = false);
  // Consecutive points joined (a spline sampled by the caller).
  void add_polyline(std::span<const glm::vec2> points_ws, glm::vec4 colour);
  // A target marker: an x of half-size `size` metres.
  void add_cross(glm::vec2 p_ws, float size, glm::vec4 colour);
  // Every collider of a level: filled with `fill`, outlined with `outline`.
  void add_level(const Level& level, glm::vec4 fill, glm::vec4 outline);

  const std::vector<DebugVertex>& lines() const { return lines_; }
  const std::vector<DebugVertex>& triangles() const { return triangles_; }
  bool empty() const { return lines_.empty() && triangles_.empty(); }

  // GL side (needs a current context): uploads and draws triangles, then lines; returns the
  // number of draw calls issued (0-2). The Debug program must be in use.
  int draw();

 private:
  std::vector<DebugVertex> lines_, triangles_;
  std::unique_ptr<VertexArray<DebugVertex>> line_va_, triangle_va_;
};

}  // namespace ossa
